#include "reference/radiance.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <numbers>
#include <random>

#include <glm/geometric.hpp>

#include "environment/equirect.h"
#include "geometry/ambient_occlusion.h"
#include "reference/area_lights.h"
#include "shading/brdf_models.h"
#include "shading/cpu_shading.h"
#include "shading/environment_brdf.h"
#include "shading/layered_brdf.h"

namespace patina {

float ggxPdf(glm::vec3 N, glm::vec3 V, glm::vec3 L, float alpha) {
    const glm::vec3 H = shader::safeNormalize(V + L);
    const float NoH = std::clamp(glm::dot(N, H), 0.0f, 1.0f), VoH = glm::dot(V, H);
    if (VoH <= 0.0f) {
        return 0.0f;
    }
    return shader::D_GGX(NoH, glm::cross(N, H), alpha) * NoH / (4.0f * VoH);
}

shader::Clearcoat referenceCoat(const ReferenceOptions& options, glm::vec3 N, glm::vec3 V) {
    return shader::deriveClearcoat(options.clearcoat, options.clearcoatRoughness, N, V);
}

shader::Sheen referenceSheen(const ReferenceOptions& options, glm::vec3 N, glm::vec3 V) {
    return shader::deriveSheen(options.sheenColor, options.sheenRoughness, N, V);
}

glm::vec3 volumeAttenuationOf(const MaterialParameters& material) {
    return shader::volumeAttenuation(material.attenuationColor, material.attenuationDistance, material.thickness);
}

ReferenceOptions withLayersOf(ReferenceOptions options, const MaterialParameters& material) {
    options.clearcoat = material.clearcoat;
    options.clearcoatRoughness = material.clearcoatRoughness;
    options.sheenColor = material.sheenColor;
    options.sheenRoughness = material.sheenRoughness;
    options.transmission = material.transmission;
    options.transmissionAttenuation = volumeAttenuationOf(material);
    return options;
}

namespace {
bool hasReferenceSheen(const ReferenceOptions& options) {
    return options.sheenColor != glm::vec3(0.0f);
}
}  // namespace

glm::vec3 coatedBrdf(const shader::BrdfValue& f, const ReferenceLayers& layers, glm::vec3 N, glm::vec3 V,
                     glm::vec3 L, const ReferenceOptions& options) {
    const glm::vec3 lobes = (options.diffuse ? f.diffuse : glm::vec3(0.0f)) +
                            (options.specular ? f.specular : glm::vec3(0.0f));
    const BrdfLayers over{options.clearcoat > 0.0f, hasReferenceSheen(options), layers.coat, layers.sheen};
    return layeredBrdf(lobes, over, N, V, L, options.specular);
}

namespace {
// The lights added exactly (every one but sphere and tube lights) into `value`: with a sheen,
// each light's base weighed by its albedo scaling and the sheen's lobe added (sheen.glsl's
// sheenLight), then the coat over them all (clearcoat.glsl's, a hemisphere light's none).
// Hemisphere lights apart only where something occludes them: one sum is the same bits.
void addExactLights(glm::vec3& value, BrdfModelId model, const shader::SurfaceMaterial& material,
                    const std::vector<shader::PackedLight>& lights, const ReferenceLayers& layers, glm::vec3 P,
                    glm::vec3 N, glm::vec3 V, const ReferenceOptions& options) {
    const bool occluded = options.indirectOcclusion != 1.0f;
    std::vector<shader::PackedLight> exact, hemispheres;
    for (const shader::PackedLight& light : lights) {
        if (!isAreaLight(light) && lightReaches(options.occluders, light, P, N)) {
            (occluded && light.type == shader::LIGHT_HEMISPHERE ? hemispheres : exact).push_back(light);
        }
    }
    const shader::Clearcoat& coat = layers.coat;
    auto overExact = [&](const std::vector<shader::PackedLight>& some) {
        glm::vec3 base(0.0f);
        if (hasReferenceSheen(options)) {
            for (const shader::PackedLight& light : some) {
                shader::SheenShare share = shader::sheenLight(light, layers.sheen, P, N, V);
                share.sheen = options.specular ? share.sheen : glm::vec3(0.0f);
                base += shader::sheenOver(shadePoint(model, material, {light}, P, N, V), share);
            }
        } else {
            base = shadePoint(model, material, some, P, N, V);
        }
        if (options.clearcoat <= 0.0f) {
            return base;
        }
        glm::vec3 layer(0.0f);
        for (const shader::PackedLight& light : some) {
            layer += options.specular ? shader::clearcoatLight(light, coat, P, V) : glm::vec3(0.0f);
        }
        return shader::clearcoatOver(base, layer, coat);
    };
    value += overExact(exact);
    if (!hemispheres.empty()) {
        value += options.indirectOcclusion * overExact(hemispheres);
    }
}

// The environment's light by multiple importance sampling over the full-resolution image:
// GGX, cosine and the image's own distribution, and the coat's GGX fourth where there is a coat
// (balance by the power heuristic, each sample's sum of strategies one value of `moments`).
SampleMoments environmentMoments(BrdfModelId model, const shader::SurfaceMaterial& material,
                                 const ReferenceEnvironment& environment, const ReferenceLayers& layers, glm::vec3 P,
                                 glm::vec3 N, glm::vec3 V, const ReferenceOptions& options) {
    const bool coated = options.clearcoat > 0.0f;
    const shader::Clearcoat& coat = layers.coat;
    const HdrImage& image = environment.environment->image;
    const glm::vec2 rotation = environmentRotation(environment.rotationDegrees);
    const float c = rotation.x, s = rotation.y;
    auto radianceFrom = [&](glm::vec3 L) {
        return environment.intensity * sampleEquirect(image, shader::toEnvironmentFrame(L, c, s));
    };
    auto integrand = [&](glm::vec3 L) {
        const float NoL = glm::dot(N, L);
        if (NoL <= 0.0f || !unoccluded(options.occluders, P, N, L, std::numeric_limits<float>::infinity())) {
            return glm::vec3(0.0f);
        }
        const shader::BrdfValue f = evaluateBrdfUnderEnvironment(model, material, N, V, L);
        return radianceFrom(L) * coatedBrdf(f, layers, N, V, L, options) * std::min(NoL, 1.0f);
    };
    // The strategies' pdfs of one direction (0 where a strategy cannot make it): the coat's
    // GGX fourth, 0 without a coat.
    auto pdfs = [&](glm::vec3 L) {
        const float NoL = glm::dot(N, L);
        const float ggx = NoL > 0.0f ? ggxPdf(N, V, L, material.alpha) : 0.0f;
        const float cosine = std::max(NoL, 0.0f) / std::numbers::pi_v<float>;
        const float env = environment.distribution->pdf(shader::toEnvironmentFrame(L, c, s));
        const float coatGgx = coated && NoL > 0.0f ? ggxPdf(N, V, L, coat.alpha) : 0.0f;
        return glm::vec4(ggx, cosine, env, coatGgx);
    };
    const int strategies = coated ? 4 : 3;
    std::mt19937_64 random(options.seed);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    SampleMoments moments;
    for (int i = 0; i < options.samples; ++i) {
        glm::vec3 L[4];
        const glm::vec3 H = shader::importanceSampleGGX(glm::vec2(uniform(random), uniform(random)), material.alpha, N);
        L[0] = 2.0f * glm::dot(V, H) * H - V;
        L[1] = sampleCosine(glm::vec2(uniform(random), uniform(random)), N);
        const EnvironmentDistribution::Sample e = environment.distribution->sample(uniform(random), uniform(random));
        L[2] = shader::toEnvironmentFrame(e.direction, c, -s);   // back to the world
        if (coated) {
            const glm::vec3 Hc = shader::importanceSampleGGX(glm::vec2(uniform(random), uniform(random)), coat.alpha, N);
            L[3] = 2.0f * glm::dot(V, Hc) * Hc - V;
        }
        glm::dvec3 x(0.0);
        for (int k = 0; k < strategies; ++k) {
            const glm::vec4 p = pdfs(L[k]);
            const float own = p[k];
            const float squares = p.x * p.x + p.y * p.y + p.z * p.z + p.w * p.w;
            if (own > 0.0f && squares > 0.0f) {
                x += glm::dvec3(integrand(L[k]) * (own / squares));   // (own^2 / squares) / own
            }
        }
        moments.add(x);
    }
    return moments;
}

// KHR_materials_transmission's light through the wall from the environment (transmission.glsl's
// f_t, thin-walled), by multiple importance sampling as the reflection's (Veach & Guibas 1995,
// the power heuristic): f_t is the reflection lobe mirrored through the surface plane, so GGX
// half-vector sampling's L, mirrored, samples it with the same pdf (ggxPdf of the unmirrored
// L); the image's own distribution samples what is bright behind the wall. By f_t alone, a rough
// glass under an HDRI of small bright windows met them as fireflies whose noise did not fall
// with the samples (docs/LIGHTING.md, "The layer grid"). Its own random stream: the base's
// estimate draws what it drew without a transmission.
SampleMoments transmissionMoments(const shader::Transmission& transmission, const ReferenceEnvironment& environment,
                                  glm::vec3 N, glm::vec3 V, const ReferenceOptions& options) {
    const glm::vec2 rotation = environmentRotation(environment.rotationDegrees);
    const float c = rotation.x, s = rotation.y;
    auto integrand = [&](glm::vec3 L) {
        const float NoL = glm::dot(N, L);
        if (!(NoL < 0.0f)) {
            return glm::vec3(0.0f);
        }
        const glm::vec3 radiance =
            environment.intensity * sampleEquirect(environment.environment->image, shader::toEnvironmentFrame(L, c, s));
        return radiance * shader::transmissionBtdf(transmission, N, V, L) * std::min(-NoL, 1.0f);
    };
    // The two strategies' pdfs of a direction through the wall: the mirrored GGX's, the image's.
    auto pdfs = [&](glm::vec3 L) {
        const float NoL = glm::dot(N, L);
        const float ggx = NoL < 0.0f ? ggxPdf(N, V, L - 2.0f * NoL * N, transmission.alpha) : 0.0f;
        return glm::vec2(ggx, environment.distribution->pdf(shader::toEnvironmentFrame(L, c, s)));
    };
    std::mt19937_64 random(options.seed ^ 0x5DEECE66Dull);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    SampleMoments moments;
    for (int i = 0; i < options.samples; ++i) {
        glm::vec3 L[2];
        const glm::vec3 H =
            shader::importanceSampleGGX(glm::vec2(uniform(random), uniform(random)), transmission.alpha, N);
        const glm::vec3 reflected = 2.0f * glm::dot(V, H) * H - V;
        L[0] = reflected - 2.0f * glm::dot(N, reflected) * N;   // through the wall
        const EnvironmentDistribution::Sample e = environment.distribution->sample(uniform(random), uniform(random));
        L[1] = shader::toEnvironmentFrame(e.direction, c, -s);   // back to the world
        glm::dvec3 x(0.0);
        for (int k = 0; k < 2; ++k) {
            const glm::vec2 p = pdfs(L[k]);
            const float own = p[k], squares = p.x * p.x + p.y * p.y;
            if (own > 0.0f && squares > 0.0f) {
                x += glm::dvec3(integrand(L[k]) * (own / squares));   // (own^2 / squares) / own
            }
        }
        moments.add(x);
    }
    return moments;
}

// The lights but the environment through the wall, as transmission.glsl gives them (the
// hemisphere lights' share occluded as their reflected light is).
glm::vec3 transmittedLights(const shader::Transmission& transmission, const std::vector<shader::PackedLight>& lights,
                            glm::vec3 P, glm::vec3 N, glm::vec3 V, const ReferenceOptions& options) {
    glm::vec3 sum(0.0f);
    for (const shader::PackedLight& light : lights) {
        const float occlusion = light.type == shader::LIGHT_HEMISPHERE ? options.indirectOcclusion : 1.0f;
        sum += occlusion * shader::transmissionLight(light, transmission, P, N, V);
    }
    return sum;
}
}  // namespace

ReferenceEstimate referenceRadiance(BrdfModelId model, const shader::SurfaceMaterial& surface,
                                    const ReferenceEnvironment& environment,
                                    const std::vector<shader::PackedLight>& lights, glm::vec3 P, glm::vec3 N,
                                    glm::vec3 V, const ReferenceOptions& options) {
    N = shader::safeNormalize(N);
    V = shader::safeNormalize(V);
    // A transmission takes its fraction of the diffuse (transmission.glsl's transmissionDiffuse).
    const bool transmits = options.transmission > 0.0f;
    const shader::Transmission transmission = shader::deriveTransmission(
        surface, options.transmission, options.transmissionAttenuation, N, V);
    const shader::SurfaceMaterial material =
        transmits ? shader::transmissionDiffuse(surface, options.transmission) : surface;
    // Sphere and tube lights by their own Monte Carlo (area_lights.h), the others exactly.
    ReferenceEstimate estimate = areaLightReference(model, material, lights, P, N, V, options);
    const ReferenceLayers layers{referenceCoat(options, N, V), referenceSheen(options, N, V)};
    addExactLights(estimate.value, model, material, lights, layers, P, N, V, options);
    // KHR_materials_sheen's albedo scaling weighs all beneath the fibres, the light through the
    // wall leaving them towards V too (sheen.glsl's sheenViewWeight).
    const float throughSheen = hasReferenceSheen(options) ? shader::sheenViewWeight(layers.sheen) : 1.0f;
    // And beneath a coat, which weighs all it covers by 1 - clearcoat fr_c (clearcoatOver, as
    // shade.frag adds the light through the wall before the coat); `transmitted` stays the
    // light as it leaves the base, the transmission channel's.
    const float throughCoat = options.clearcoat > 0.0f ? shader::clearcoatBaseWeight(layers.coat) : 1.0f;
    if (transmits) {
        estimate.transmitted = throughSheen * transmittedLights(transmission, lights, P, N, V, options);
        estimate.value += throughCoat * estimate.transmitted;
    }
    if (!environment.environment || !(glm::dot(N, N) > 0.0f) || options.samples < 1) {
        return estimate;
    }
    const SampleMoments moments = environmentMoments(model, material, environment, layers, P, N, V, options);
    const double n = double(options.samples);
    const double occlusion = options.indirectOcclusion;
    glm::dvec3 variance = moments.varianceOfMean(n) * (occlusion * occlusion);
    estimate.value += glm::vec3(moments.mean(n) * occlusion);
    if (transmits) {
        const SampleMoments through = transmissionMoments(transmission, environment, N, V, options);
        const double weight = occlusion * double(throughSheen), covered = weight * double(throughCoat);
        variance += through.varianceOfMean(n) * (covered * covered);
        estimate.transmitted += glm::vec3(through.mean(n) * weight);
        estimate.value += glm::vec3(through.mean(n) * covered);
    }
    // Independent estimates: their variances add.
    estimate.standardError = glm::vec3(glm::sqrt(variance + glm::dvec3(estimate.standardError * estimate.standardError)));
    return estimate;
}

}  // namespace patina
