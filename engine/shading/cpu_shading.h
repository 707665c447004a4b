#pragma once
#include <vector>

#include <glm/vec3.hpp>

#include "shading/material_parameters.h"
#include "shading/shading.h"

namespace patina {

shader::SurfaceMaterial surfaceMaterial(const MaterialParameters& material);

// Linear radiance towards V at P with normal N, summed over the packed lights: the CPU twin
// of shaders/stages/shade.frag's single-pass loop, running the same shared functions for `model`.
glm::vec3 shadePoint(BrdfModelId model, const shader::SurfaceMaterial& material,
                     const std::vector<shader::PackedLight>& lights, glm::vec3 position,
                     glm::vec3 normal, glm::vec3 toViewer);

}  // namespace patina
