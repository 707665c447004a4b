#include "gl/surface_map_uniforms.h"

#include <glm/gtc/type_ptr.hpp>

namespace patina {

namespace {
constexpr const char* kSamplerNames[kSurfaceMapCount] = {
    "uBaseColorMap", "uMetallicRoughnessMap", "uNormalMap",      "uOcclusionMap",
    "uEmissiveMap",  "uClearcoatMap",         "uClearcoatRoughnessMap", "uClearcoatNormalMap",
    "uSheenColorMap", "uSheenRoughnessMap",   "uTransmissionMap",       "uThicknessMap",
    "uSpecularColorMap", "uSpecularMap", "uIridescenceMap", "uIridescenceThicknessMap",
    "uAnisotropyMap"};

}  // namespace

SurfaceMapUniforms::SurfaceMapUniforms(const GlProgram& program, int firstUnit)
    : firstUnit_(firstUnit), placement_(program.uniform("uMapPlacement")),
      rotationSet_(program.uniform("uMapRotationSet")), baseAlpha_(program.uniform("uBaseAlpha")),
      alphaCutoff_(program.uniform("uAlphaCutoff")), normalScale_(program.uniform("uNormalScale")),
      occlusionStrength_(program.uniform("uOcclusionStrength")), emissive_(program.uniform("uEmissive")),
      clearcoatNormalScale_(program.uniform("uClearcoatNormalScale")) {
    for (int map = 0; map < kSurfaceMapCount; ++map) {
        glUniform1i(program.uniform(kSamplerNames[map]), firstUnit + map);
    }
}

void SurfaceMapUniforms::set(const SceneDraw& draw, ModelTextures& textures) const {
    std::array<glm::vec4, kSurfaceMapCount> placement;
    std::array<glm::vec2, kSurfaceMapCount> rotationSet;
    placement.fill(glm::vec4(0.0f, 0.0f, 1.0f, 1.0f));
    rotationSet.fill(glm::vec2(0.0f, -1.0f));   // no map
    const ModelMaterial* material = draw.maps;
    if (material) {
        const auto maps = mapsOf(*material);
        for (int map = 0; map < kSurfaceMapCount; ++map) {
            const TextureSlot& slot = *maps[size_t(map)].slot;
            if (textures.bind(firstUnit_ + map, slot, maps[size_t(map)].srgb)) {
                placement[size_t(map)] = glm::vec4(slot.transform.offset, slot.transform.scale);
                rotationSet[size_t(map)] = glm::vec2(slot.transform.rotation, float(slot.texCoord));
            }
        }
        glActiveTexture(GL_TEXTURE0);
    }
    glUniform4fv(placement_, kSurfaceMapCount, glm::value_ptr(placement[0]));
    glUniform2fv(rotationSet_, kSurfaceMapCount, glm::value_ptr(rotationSet[0]));
    glUniform1f(baseAlpha_, material ? material->baseAlpha : 1.0f);
    glUniform1f(alphaCutoff_, draw.alphaCutoff);
    glUniform1f(normalScale_, material ? material->normalScale : 1.0f);
    glUniform1f(occlusionStrength_, material ? material->occlusionStrength : 1.0f);
    const glm::vec3 emissive = material ? material->emissiveFactor : glm::vec3(0.0f);
    glUniform3fv(emissive_, 1, glm::value_ptr(emissive));
    glUniform1f(clearcoatNormalScale_, material ? material->clearcoatNormalScale : 1.0f);
}

}  // namespace patina
