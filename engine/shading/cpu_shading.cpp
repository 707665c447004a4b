#include "shading/cpu_shading.h"

#include <cmath>

#include "shading/brdf_models.h"

namespace patina {

shader::SurfaceMaterial surfaceMaterial(const MaterialParameters& material) {
    const shader::SurfaceMaterial specular = shader::withSpecular(
        shader::deriveSurfaceMaterial(material.baseColor, material.roughness, material.specular, material.metallic),
        material.specularTint, material.specularWeight);
    // The film's thickness as the maps leave it in the maximum (engine/reference/surface_maps.cpp).
    return shader::withIridescence(specular, material.iridescence, material.iridescenceIor,
                                   material.iridescenceThicknessMaximum);
}

shader::SurfaceMaterial surfaceMaterialAt(const MaterialParameters& material, glm::vec3 N, glm::vec4 tangent) {
    const shader::SurfaceMaterial surface = surfaceMaterial(material);
    if (!(material.anisotropyStrength > 0.0f)) {
        return surface;
    }
    return shader::withAnisotropy(surface, N, glm::vec3(tangent), tangent.w, std::cos(material.anisotropyRotation),
                                  std::sin(material.anisotropyRotation), material.anisotropyStrength);
}

shader::SurfaceMaterial surfaceMaterialInLobeFrame(const MaterialParameters& material) {
    return surfaceMaterialAt(material, glm::vec3(0.0f, 0.0f, 1.0f), glm::vec4(1.0f, 0.0f, 0.0f, 1.0f));
}

glm::vec3 shadePoint(BrdfModelId model, const shader::SurfaceMaterial& material,
                     const std::vector<shader::PackedLight>& lights, glm::vec3 position,
                     glm::vec3 normal, glm::vec3 toViewer) {
    const glm::vec3 N = shader::safeNormalize(normal);
    const glm::vec3 V = shader::safeNormalize(toViewer);
    glm::vec3 radiance(0.0f);
    for (const shader::PackedLight& light : lights) {
        radiance += shadeLight(model, light, material, position, N, V);
    }
    return radiance;
}

}  // namespace patina
