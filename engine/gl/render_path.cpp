#include "gl/render_path.h"

#include "common/enum_names.h"

namespace patina {

std::string_view renderPathName(RenderPath mode) {
    switch (mode) {
    case RenderPath::Single: return "single";
    case RenderPath::Multi: return "multi";
    case RenderPath::Specialised: return "specialised";
    }
    return "single";
}

std::optional<RenderPath> renderPathFromName(std::string_view name) {
    static const RenderPath all[] = {RenderPath::Single, RenderPath::Multi, RenderPath::Specialised};
    return enumFromName(name, all, renderPathName);
}

}  // namespace patina
