#include "accuracy/accuracy.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <random>

#include "shading/cpu_shading.h"

namespace patina {

namespace {
// NoV, NoL >= 0.01: the well-defined region of docs/SHADING.md S2.
const double kMaxTheta = std::acos(0.01);

// Latin hypercube: each of `count` strata of [0, 1) used once per dimension, jittered.
std::vector<double> latinHypercube(int count, std::mt19937& rng) {
    std::vector<int> order(static_cast<size_t>(count));
    std::iota(order.begin(), order.end(), 0);
    std::shuffle(order.begin(), order.end(), rng);
    std::uniform_real_distribution<double> jitter(0.0, 1.0);
    std::vector<double> values;
    for (int stratum : order) {
        values.push_back((stratum + jitter(rng)) / count);
    }
    return values;
}
}  // namespace

AccuracySet stratifiedAccuracySet(int roughnessStrata, int metallicStrata, int specularStrata, int perMaterial,
                                  uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> jitter(0.0, 1.0);
    AccuracySet set;
    const glm::dvec3 L(0.0, 0.0, 1.0);
    for (int ri = 0; ri < roughnessStrata; ++ri) {
        for (int mi = 0; mi < metallicStrata; ++mi) {
            for (int si = 0; si < specularStrata; ++si) {
                Material material;
                material.baseColor = {0.8f, 0.5f, 0.25f};
                // r in [0.05, 1]: below that is the guards' territory (the stability sweep).
                material.roughness = float(0.05 + 0.95 * (ri + jitter(rng)) / roughnessStrata);
                material.metallic = float((mi + jitter(rng)) / metallicStrata);
                material.specular = float((si + jitter(rng)) / specularStrata);
                set.materialStart.push_back(set.samples.size());
                const std::vector<double> thetaV = latinHypercube(perMaterial, rng);
                const std::vector<double> thetaL = latinHypercube(perMaterial, rng);
                const std::vector<double> phi = latinHypercube(perMaterial, rng);
                for (int i = 0; i < perMaterial; ++i) {
                    // N at theta_l from L; V at theta_v from N, phi from the plane of N and L.
                    const double tl = thetaL[size_t(i)] * kMaxTheta, tv = thetaV[size_t(i)] * kMaxTheta;
                    const double p = phi[size_t(i)] * 2.0 * std::numbers::pi;
                    const glm::dvec3 N(std::sin(tl), 0.0, std::cos(tl));
                    const glm::dvec3 t = tl > 1e-9 ? glm::normalize(L - std::cos(tl) * N) : glm::dvec3(1, 0, 0);
                    const glm::dvec3 b = glm::cross(N, t);
                    const glm::dvec3 V = std::sin(tv) * std::cos(p) * t + std::sin(tv) * std::sin(p) * b + std::cos(tv) * N;
                    set.samples.push_back({material, N, V, L});
                }
            }
        }
    }
    set.materialStart.push_back(set.samples.size());
    return set;
}

void ErrorAccumulator::add(glm::dvec3 value, glm::dvec3 expected) {
    for (int c = 0; c < 3; ++c) {
        const double error = value[c] - expected[c];
        squaredError_ += error * error;
        squaredExpected_ += expected[c] * expected[c];
        if (std::abs(expected[c]) > 1e-4) {
            maxRelative_ = std::max(maxRelative_, std::abs(error) / std::abs(expected[c]));
        } else if (!std::isfinite(value[c])) {
            maxRelative_ = INFINITY;
        }
    }
}

ErrorStats ErrorAccumulator::stats() const {
    return {squaredExpected_ > 0 ? std::sqrt(squaredError_ / squaredExpected_) : 0.0, maxRelative_};
}

glm::dvec3 reflectedF64(BrdfModelId model, const AccuracySample& sample) {
    const BrdfValueF64 f = evaluateBrdfF64(model, sample.material, sample.N, sample.V, sample.L);
    return (f.diffuse + f.specular) * glm::dot(sample.N, sample.L);
}

glm::dvec3 reflectedF32(BrdfModelId model, const AccuracySample& sample) {
    const glm::vec3 N(sample.N), V(sample.V), L(sample.L);
    const shader::BrdfValue f = evaluateBrdf(model, surfaceMaterial(sample.material), N, V, L);
    return glm::dvec3((f.diffuse + f.specular) * glm::dot(N, L));
}

ErrorStats cpuImplementationError(BrdfModelId model, const AccuracySet& set) {
    ErrorAccumulator errors;
    for (const AccuracySample& sample : set.samples) {
        errors.add(reflectedF32(model, sample), reflectedF64(model, sample));
    }
    return errors.stats();
}

ErrorStats physicalError(BrdfModelId model, const AccuracySet& set) {
    ErrorAccumulator errors;
    for (const AccuracySample& sample : set.samples) {
        errors.add(reflectedF64(model, sample), reflectedF64(BrdfModelId::Reference, sample));
    }
    return errors.stats();
}

std::vector<ProbeSample> probeSamples(const AccuracySet& set, size_t material) {
    std::vector<ProbeSample> samples;
    for (size_t i = set.materialStart[material]; i < set.materialStart[material + 1]; ++i) {
        const AccuracySample& s = set.samples[i];
        samples.push_back({glm::vec3(0.0f), glm::vec3(s.N), glm::vec3(s.V)});
    }
    return samples;
}

Light accuracyLight() {
    Light light;
    light.type = LightType::Directional;
    light.direction = {0.0f, 0.0f, -1.0f};   // travels down -z: L = +z
    light.intensity = 1.0f;
    light.color = glm::vec3(1.0f);
    return light;
}

}  // namespace patina
