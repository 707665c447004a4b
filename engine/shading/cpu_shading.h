#pragma once
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "shading/material_parameters.h"
#include "shading/shading.h"

namespace patina {

shader::SurfaceMaterial surfaceMaterial(const MaterialParameters& material);
// The same at a point of the surface, with KHR_materials_anisotropy's lobe where the material
// has one (hasAnisotropy): shade.frag's withAnisotropy on the unit shading normal N and the
// mesh's tangent there (xyz and w as mesh.vert hands it on; w = 0: none, the fallback's).
shader::SurfaceMaterial surfaceMaterialAt(const MaterialParameters& material, glm::vec3 N, glm::vec4 tangent);
// The same in the lobe views' frame (shading/lobe.h, the albedo curve, the lobe panel's terms):
// N = (0, 0, 1) and the tangent along +x, the polar plot's plane of incidence, so that an
// anisotropic lobe is stretched along the rotation turned from x (0: in that plane).
shader::SurfaceMaterial surfaceMaterialInLobeFrame(const MaterialParameters& material);

// Linear radiance towards V at P with normal N, summed over the packed lights: the CPU twin
// of shaders/stages/shade.frag's single-pass loop, running the same shared functions for `model`.
glm::vec3 shadePoint(BrdfModelId model, const shader::SurfaceMaterial& material,
                     const std::vector<shader::PackedLight>& lights, glm::vec3 position,
                     glm::vec3 normal, glm::vec3 toViewer);

}  // namespace patina
