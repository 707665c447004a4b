#include "gl/environment_method.h"

#include "common/enum_names.h"

namespace patina {

std::string_view environmentMethodName(EnvironmentMethod method) {
    switch (method) {
    case EnvironmentMethod::SplitSum: return "split-sum";
    case EnvironmentMethod::Dominant: return "dominant";
    case EnvironmentMethod::Stochastic: return "stochastic";
    }
    return "split-sum";
}

std::optional<EnvironmentMethod> environmentMethodFromName(std::string_view name) {
    static const EnvironmentMethod all[] = {EnvironmentMethod::SplitSum, EnvironmentMethod::Dominant,
                                            EnvironmentMethod::Stochastic};
    return enumFromName(name, all, environmentMethodName);
}

}  // namespace patina
