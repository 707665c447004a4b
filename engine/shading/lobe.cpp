#include "shading/lobe.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "shading/brdf_models.h"
#include "shading/cpu_shading.h"
#include "shading/layered_brdf.h"

namespace patina {

namespace {
// KHR_materials_transmission's thin-walled BTDF (transmission.glsl's transmissionBtdf, glTF 2.0
// Appendix B's specular_btdf as the extension mirrors it) from unit L above towards unit `below`
// beneath the surface, tinted and attenuated (the material's own thickness: a lobe has no draw's
// scale). f_t is reciprocal (D, Vis and F(V.H) are symmetric in the two directions once one is
// mirrored), so it is the BTDF seen from L with the light at `below`, and the layers above weigh
// it as they weigh what leaves towards L. 0 without a transmission.
glm::vec3 transmittedLobe(const MaterialParameters& material, glm::vec3 N, glm::vec3 L, glm::vec3 below) {
    if (!(material.transmission > 0.0f)) {
        return glm::vec3(0.0f);
    }
    const glm::vec3 attenuation =
        shader::volumeAttenuation(material.attenuationColor, material.attenuationDistance, material.thickness);
    const shader::Transmission t =
        shader::deriveTransmission(surfaceMaterialInLobeFrame(material), material.transmission, attenuation, N, L);
    return layeredTransmission(shader::transmissionBtdf(t, N, L, below), brdfLayers(material, N, L));
}

// The material the reflected lobes read (stretched along x turned by its rotation where it is
// anisotropic): its diffuse what a transmission leaves of it.
shader::SurfaceMaterial reflectingSurface(const MaterialParameters& material) {
    const shader::SurfaceMaterial surface = surfaceMaterialInLobeFrame(material);
    return material.transmission > 0.0f ? shader::transmissionDiffuse(surface, material.transmission) : surface;
}
}  // namespace

LobeValue lobeValue(const MaterialParameters& material, glm::vec3 L, glm::vec3 V) {
    const glm::vec3 N(0.0f, 0.0f, 1.0f);
    const shader::BrdfValue f = evaluateBrdf(material.model, reflectingSurface(material), N, V, L);
    const BrdfLayers layers = brdfLayers(material, N, V);
    LobeValue value;
    value.diffuse = layeredBrdf(f.diffuse, layers, N, V, L, false);
    value.specular = layeredBrdf(f.specular, layers, N, V, L, false);
    // The layers' own terms alone (the sheen's under the coat): layeredBrdf is linear in the
    // base's lobes, so over no base it is what the layers add.
    value.layers = layeredBrdf(glm::vec3(0.0f), layers, N, V, L);
    value.transmitted = transmittedLobe(material, N, L, glm::vec3(V.x, V.y, -V.z));
    return value;
}

std::vector<LobeSample> evaluateLobe(const MaterialParameters& material, float thetaInDegrees, int samples) {
    const float thetaIn = glm::radians(thetaInDegrees);
    const glm::vec3 L(std::sin(thetaIn), 0.0f, std::cos(thetaIn));
    std::vector<LobeSample> lobe;
    lobe.reserve(size_t(samples));
    for (int i = 0; i < samples; ++i) {
        const float thetaOutDegrees = -90.0f + 180.0f * float(i) / float(samples - 1);
        const float thetaOut = glm::radians(thetaOutDegrees);
        lobe.push_back({lobeValue(material, L, glm::vec3(std::sin(thetaOut), 0.0f, std::cos(thetaOut))), thetaOutDegrees});
    }
    return lobe;
}

std::string formatLobeCsv(const std::vector<LobeSample>& lobe) {
    const bool layered =
        std::any_of(lobe.begin(), lobe.end(), [](const LobeSample& sample) { return sample.layers != glm::vec3(0.0f); });
    const bool transmits = std::any_of(lobe.begin(), lobe.end(),
                                       [](const LobeSample& sample) { return sample.transmitted != glm::vec3(0.0f); });
    std::string out = "theta_out_deg,diffuse_r,diffuse_g,diffuse_b,specular_r,specular_g,specular_b,";
    out += layered ? "layers_r,layers_g,layers_b,total_r,total_g,total_b" : "total_r,total_g,total_b";
    out += transmits ? ",transmitted_r,transmitted_g,transmitted_b\n" : "\n";
    char cell[32];
    for (const LobeSample& sample : lobe) {
        std::vector<glm::vec3> columns{sample.diffuse, sample.specular};
        if (layered) {
            columns.push_back(sample.layers);
        }
        columns.push_back(sample.total());
        if (transmits) {
            columns.push_back(sample.transmitted);
        }
        std::snprintf(cell, sizeof cell, "%.9g", double(sample.thetaOutDegrees));
        out += cell;
        for (const glm::vec3& column : columns) {
            for (int c = 0; c < 3; ++c) {
                std::snprintf(cell, sizeof cell, ",%.9g", double(column[c]));
                out += cell;
            }
        }
        out += "\n";
    }
    return out;
}

}  // namespace patina
