#include "scene/light.h"

#include "common/enum_names.h"

namespace patina {

std::string_view lightTypeName(LightType type) {
    switch (type) {
    case LightType::Point: return "point";
    case LightType::Directional: return "directional";
    case LightType::Hemisphere: return "hemisphere";
    case LightType::Environment: return "environment";
    case LightType::Sphere: return "sphere";
    case LightType::Tube: return "tube";
    }
    return "point";
}

std::optional<LightType> lightTypeFromName(std::string_view name) {
    static const LightType all[] = {LightType::Point,       LightType::Directional, LightType::Hemisphere,
                                    LightType::Environment, LightType::Sphere,      LightType::Tube};
    return enumFromName(name, all, lightTypeName);
}

bool castsShadows(LightType type) {
    return type != LightType::Hemisphere && type != LightType::Environment;
}

}  // namespace patina
