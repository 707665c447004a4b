#include "shading/layered_brdf.h"

namespace patina {

BrdfLayers brdfLayers(float clearcoat, float clearcoatRoughness, glm::vec3 sheenColor, float sheenRoughness,
                      glm::vec3 N, glm::vec3 V) {
    return {clearcoat > 0.0f, sheenColor != glm::vec3(0.0f), shader::deriveClearcoat(clearcoat, clearcoatRoughness, N, V),
            shader::deriveSheen(sheenColor, sheenRoughness, N, V)};
}

glm::vec3 layeredBrdf(glm::vec3 lobes, const BrdfLayers& layers, glm::vec3 N, glm::vec3 V, glm::vec3 L,
                      bool ownLobes) {
    if (layers.sheened) {
        const glm::vec3 lobe = ownLobes ? shader::sheenBrdf(layers.sheen, N, V, L) : glm::vec3(0.0f);
        lobes = shader::sheenOver(lobes, shader::SheenShare(lobe, shader::sheenBaseWeight(layers.sheen, glm::dot(N, L))));
    }
    if (!layers.coated) {
        return lobes;
    }
    const float layer = ownLobes ? shader::clearcoatBrdf(layers.coat, V, L) : 0.0f;
    return shader::clearcoatOver(lobes, glm::vec3(layer), layers.coat);
}

glm::vec3 layeredTransmission(glm::vec3 transmitted, const BrdfLayers& layers) {
    if (layers.sheened) {
        transmitted *= shader::sheenViewWeight(layers.sheen);
    }
    return layers.coated ? shader::clearcoatOver(transmitted, glm::vec3(0.0f), layers.coat) : transmitted;
}

}  // namespace patina
