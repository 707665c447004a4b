#include "shading/lobe.h"

#include <cmath>
#include <cstdio>

#include "shading/brdf_models.h"
#include "shading/cpu_shading.h"

namespace patina {

std::vector<LobeSample> evaluateLobe(const MaterialParameters& material, float thetaInDegrees, int samples) {
    const shader::SurfaceMaterial surface = surfaceMaterial(material);
    const glm::vec3 N(0.0f, 0.0f, 1.0f);
    const float thetaIn = glm::radians(thetaInDegrees);
    const glm::vec3 L(std::sin(thetaIn), 0.0f, std::cos(thetaIn));
    std::vector<LobeSample> lobe;
    lobe.reserve(size_t(samples));
    for (int i = 0; i < samples; ++i) {
        const float thetaOutDegrees = -90.0f + 180.0f * float(i) / float(samples - 1);
        const float thetaOut = glm::radians(thetaOutDegrees);
        const glm::vec3 V(std::sin(thetaOut), 0.0f, std::cos(thetaOut));
        const shader::BrdfValue f = evaluateBrdf(material.model, surface, N, V, L);
        lobe.push_back({thetaOutDegrees, f.diffuse, f.specular});
    }
    return lobe;
}

std::string formatLobeCsv(const std::vector<LobeSample>& lobe) {
    std::string out =
        "theta_out_deg,diffuse_r,diffuse_g,diffuse_b,specular_r,specular_g,specular_b,"
        "total_r,total_g,total_b\n";
    char row[256];
    for (const LobeSample& sample : lobe) {
        const glm::vec3 t = sample.total();
        std::snprintf(row, sizeof row, "%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n",
                      double(sample.thetaOutDegrees), double(sample.diffuse.r),
                      double(sample.diffuse.g), double(sample.diffuse.b),
                      double(sample.specular.r), double(sample.specular.g),
                      double(sample.specular.b), double(t.r), double(t.g), double(t.b));
        out += row;
    }
    return out;
}

}  // namespace patina
