#pragma once
#include <string>

#include "scene/json_value.h"
#include "shading/material_parameters.h"

namespace patina {

// A material as Patina keeps it: the parameters the BRDF reads, and what a file holds beside
// them.
struct Material : MaterialParameters {
    std::string name = "default";
    std::string notes{};   // where the numbers come from; shading ignores it
    // Keys of the file Patina does not know, kept so that saving writes them back.
    Json extras = Json::object();
    bool operator==(const Material&) const = default;
};

}  // namespace patina
