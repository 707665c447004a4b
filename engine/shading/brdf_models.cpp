#include "shading/brdf_models.h"

#include <algorithm>
#include <cmath>
#include <iterator>

#include "shading/channel_inputs.h"
#include "shading/energy_table.h"
#include "shading/environment_brdf.h"
#include "shading/shading_f16.h"
#include "shading/shading_f64.h"

// Every model's permutation in fp32, fp64 and emulated fp16, each in the namespace whose `real`
// it takes (engine/shading/shading.h, shading_f64.h, shading_f16.h).
// Image-based lighting (ibl.glsl) is compiled in fp32 only: the GPU's precision.
namespace patina::shader {
#define PATINA_WITH_IBL
#include "shading/brdf_model_instances.h"
#undef PATINA_WITH_IBL
}  // namespace patina::shader

namespace patina::shader_f64 {
#include "shading/brdf_model_instances.h"
}  // namespace patina::shader_f64

namespace patina::shader_f16 {
#define PATINA_NO_THIN_FILM   // iridescence.glsl is not in fp16 (shaders/shared/brdf.glsl)
#include "shading/brdf_model_instances.h"
#undef PATINA_NO_THIN_FILM
}  // namespace patina::shader_f16

namespace patina {

namespace {
constexpr BrdfModelInfo kModels[] = {
#define PATINA_MODEL_INFO(id, name, summary) {BrdfModelId::id, name, {PATINA_TERMS_OF(id)}, summary},
    PATINA_BRDF_MODELS(PATINA_MODEL_INFO)
#undef PATINA_MODEL_INFO
};
}  // namespace

std::span<const BrdfModelInfo> brdfModels() {
    return kModels;
}

const BrdfModelInfo& brdfModel(BrdfModelId id) {
    return kModels[size_t(id)];
}

std::optional<BrdfModelId> brdfModelFromName(std::string_view name) {
    for (const BrdfModelInfo& model : kModels) {
        if (model.name == name) {
            return model.id;
        }
    }
    return std::nullopt;
}

std::string brdfModelNames() {
    std::string names;
    for (const BrdfModelInfo& model : kModels) {
        names += (names.empty() ? "" : ", ") + std::string(model.name);
    }
    return names;
}

std::vector<std::string> brdfModelDefines(BrdfModelId id) {
    const BrdfTerms& t = brdfModel(id).terms;
    return {"PATINA_D " + std::to_string(t.d), "PATINA_V " + std::to_string(t.v),
            "PATINA_F " + std::to_string(t.f), "PATINA_FD " + std::to_string(t.fd),
            "PATINA_MS " + std::to_string(t.ms)};
}

// Runtime dispatch to the compile-time permutations: one case per model.
#define PATINA_CASE(space, model, call) \
    case BrdfModelId::model:            \
        return space::PATINA_MODEL_NAMESPACE(model)::call;

shader::BrdfValue evaluateBrdf(BrdfModelId id, const shader::SurfaceMaterial& material, glm::vec3 N,
                               glm::vec3 V, glm::vec3 L) {
    switch (id) {
#define PATINA_EVALUATE(model, name, summary) PATINA_CASE(shader, model, evaluateBrdf(material, N, V, L))
        PATINA_BRDF_MODELS(PATINA_EVALUATE)
#undef PATINA_EVALUATE
    }
    return shader::model_Epic::evaluateBrdf(material, N, V, L);
}

shader::SpecularTerms specularTerms(BrdfModelId id, const shader::SurfaceMaterial& material, glm::vec3 N,
                                    glm::vec3 V, glm::vec3 L) {
    switch (id) {
#define PATINA_TERMS(model, name, summary) PATINA_CASE(shader, model, specularTerms(material, N, V, L))
        PATINA_BRDF_MODELS(PATINA_TERMS)
#undef PATINA_TERMS
    }
    return shader::model_Epic::specularTerms(material, N, V, L);
}

glm::vec3 shadeLight(BrdfModelId id, const shader::PackedLight& light, const shader::SurfaceMaterial& material,
                     glm::vec3 P, glm::vec3 N, glm::vec3 V) {
    switch (id) {
#define PATINA_SHADE(model, name, summary) PATINA_CASE(shader, model, shadeLight(light, material, P, N, V))
        PATINA_BRDF_MODELS(PATINA_SHADE)
#undef PATINA_SHADE
    }
    return shader::model_Epic::shadeLight(light, material, P, N, V);
}

glm::vec3 shadeAreaLight(BrdfModelId id, const shader::PackedLight& light, shader::AreaLightMethod method,
                         const shader::SurfaceMaterial& material, glm::vec3 P, glm::vec3 N, glm::vec3 V) {
    switch (id) {
#define PATINA_SHADE(model, name, summary) PATINA_CASE(shader, model, shadeAreaLightWith(light, method, material, P, N, V))
        PATINA_BRDF_MODELS(PATINA_SHADE)
#undef PATINA_SHADE
    }
    return shader::model_Epic::shadeAreaLightWith(light, method, material, P, N, V);
}

BrdfValueF64 evaluateBrdfF64(BrdfModelId id, const MaterialParameters& material, glm::dvec3 N, glm::dvec3 V,
                             glm::dvec3 L) {
    const shader_f64::SurfaceMaterial m = shader_f64::withIridescence(
        shader_f64::withSpecular(shader_f64::deriveSurfaceMaterial(glm::dvec3(material.baseColor), material.roughness,
                                                                   material.specular, material.metallic),
                                 glm::dvec3(material.specularTint), material.specularWeight),
        material.iridescence, material.iridescenceIor, material.iridescenceThicknessMaximum);
    switch (id) {
#define PATINA_EVALUATE(model, name, summary)                                                   \
    case BrdfModelId::model: {                                                                 \
        const shader_f64::BrdfValue f = shader_f64::PATINA_MODEL_NAMESPACE(model)::evaluateBrdf(m, N, V, L); \
        return {f.diffuse, f.specular};                                                        \
    }
        PATINA_BRDF_MODELS(PATINA_EVALUATE)
#undef PATINA_EVALUATE
    }
    return {};
}

glm::vec2 integrateEnvironmentBrdf(BrdfModelId id, float NoV, float roughness, unsigned samples) {
    switch (id) {
#define PATINA_INTEGRATE(model, name, summary) PATINA_CASE(shader, model, integrateEnvironmentBrdf(NoV, roughness, samples))
        PATINA_BRDF_MODELS(PATINA_INTEGRATE)
#undef PATINA_INTEGRATE
    }
    return glm::vec2(0.0f);
}

glm::vec2 environmentBrdf(BrdfModelId id, float NoV, float roughness) {
    switch (id) {
#define PATINA_LOOKUP(model, name, summary) PATINA_CASE(shader, model, environmentBrdfLookup(NoV, roughness))
        PATINA_BRDF_MODELS(PATINA_LOOKUP)
#undef PATINA_LOOKUP
    }
    return glm::vec2(0.0f);
}

glm::vec2 environmentRotation(float rotationDegrees) {
    const float radians = glm::radians(rotationDegrees);
    return {std::cos(radians), std::sin(radians)};
}

glm::vec3 shadeEnvironment(BrdfModelId id, shader::EnvironmentSource prefiltered, float maxLod,
                           shader::EnvironmentSource irradiance, float intensity, float rotationDegrees,
                           const shader::SurfaceMaterial& material, glm::vec3 N, glm::vec3 V, bool dominant) {
    const glm::vec2 rotation = environmentRotation(rotationDegrees);
    const float c = rotation.x, s = rotation.y;
    switch (id) {
#define PATINA_SHADE(model, name, summary)                                                                      \
    PATINA_CASE(shader, model,                                                                                  \
                shadeEnvironment(prefiltered, maxLod, irradiance, intensity, c, s, material, N, V, dominant))
        PATINA_BRDF_MODELS(PATINA_SHADE)
#undef PATINA_SHADE
    }
    return glm::vec3(0.0f);
}

glm::vec3 clearcoatEnvironment(BrdfModelId id, shader::EnvironmentSource prefiltered, float maxLod, float intensity,
                               float rotationDegrees, const shader::Clearcoat& coat, glm::vec3 V) {
    const glm::vec2 rotation = environmentRotation(rotationDegrees);
    switch (id) {
#define PATINA_SHADE(model, name, summary) \
    PATINA_CASE(shader, model, clearcoatEnvironment(prefiltered, maxLod, rotation.x, rotation.y, coat, V) * intensity)
        PATINA_BRDF_MODELS(PATINA_SHADE)
#undef PATINA_SHADE
    }
    return glm::vec3(0.0f);
}

glm::vec3 transmissionEnvironment(BrdfModelId id, shader::EnvironmentSource prefiltered, float maxLod, float intensity,
                                  float rotationDegrees, const shader::SurfaceMaterial& material,
                                  const shader::Transmission& transmission, glm::vec3 V) {
    const glm::vec2 rotation = environmentRotation(rotationDegrees);
    switch (id) {
#define PATINA_SHADE(model, name, summary)                                                                         \
    PATINA_CASE(shader, model,                                                                                     \
                transmissionEnvironment(prefiltered, maxLod, rotation.x, rotation.y, material, transmission, V) * \
                    intensity)
        PATINA_BRDF_MODELS(PATINA_SHADE)
#undef PATINA_SHADE
    }
    return glm::vec3(0.0f);
}

glm::vec3 shadeEnvironmentStochastic(BrdfModelId id, shader::EnvironmentSource source, float sourceFaceSize,
                                     shader::EnvironmentSource irradiance, float intensity, float rotationDegrees,
                                     const shader::SurfaceMaterial& material, glm::vec3 N, glm::vec3 V,
                                     unsigned count, glm::vec2 jitter) {
    const glm::vec2 rotation = environmentRotation(rotationDegrees);
    switch (id) {
#define PATINA_SHADE(model, name, summary)                                                                        \
    PATINA_CASE(shader, model,                                                                                    \
                shadeEnvironmentStochastic(source, sourceFaceSize, irradiance, intensity, rotation.x, rotation.y, \
                                           material, N, V, count, jitter))
        PATINA_BRDF_MODELS(PATINA_SHADE)
#undef PATINA_SHADE
    }
    return glm::vec3(0.0f);
}

shader::BrdfValue evaluateBrdfUnderEnvironment(BrdfModelId id, const shader::SurfaceMaterial& material,
                                               glm::vec3 N, glm::vec3 V, glm::vec3 L) {
    switch (id) {
#define PATINA_EVALUATE(model, name, summary) PATINA_CASE(shader, model, evaluateBrdfFor(material, N, V, L, true))
        PATINA_BRDF_MODELS(PATINA_EVALUATE)
#undef PATINA_EVALUATE
    }
    return shader::model_Epic::evaluateBrdfFor(material, N, V, L, true);
}

float tabulatedAlbedo(BrdfModelId id, float NoV, float roughness) {
    switch (id) {
#define PATINA_LOOKUP(model, name, summary) PATINA_CASE(shader, model, energyTableLookup(NoV, roughness))
        PATINA_BRDF_MODELS(PATINA_LOOKUP)
#undef PATINA_LOOKUP
    }
    return 1.0f;
}

glm::dvec3 reflectedF16(BrdfModelId id, const MaterialParameters& material, glm::dvec3 N, glm::dvec3 V, glm::dvec3 L) {
    auto half3 = [](glm::dvec3 v) { return HalfVec3(Half(v.x), Half(v.y), Half(v.z)); };
    const shader_f16::SurfaceMaterial m = shader_f16::withSpecular(
        shader_f16::deriveSurfaceMaterial(half3(glm::dvec3(material.baseColor)), Half(material.roughness),
                                          Half(material.specular), Half(material.metallic)),
        half3(glm::dvec3(material.specularTint)), Half(material.specularWeight));
    const HalfVec3 n = half3(N), v = half3(V), l = half3(L);
    shader_f16::BrdfValue f{};
    switch (id) {
#define PATINA_EVALUATE(model, name, summary) \
    case BrdfModelId::model: f = shader_f16::PATINA_MODEL_NAMESPACE(model)::evaluateBrdf(m, n, v, l); break;
        PATINA_BRDF_MODELS(PATINA_EVALUATE)
#undef PATINA_EVALUATE
    }
    const HalfVec3 reflected = (f.diffuse + f.specular) * half_glsl::max(half_glsl::dot(n, l), Half(0.0f));
    return {double(reflected.x), double(reflected.y), double(reflected.z)};
}

double specularLobeF64(BrdfModelId id, double roughness, glm::dvec3 N, glm::dvec3 V, glm::dvec3 L) {
    const shader_f64::SurfaceMaterial m = shader_f64::deriveSurfaceMaterial(glm::dvec3(1.0), roughness, 0.5, 0.0);
    switch (id) {
#define PATINA_LOBE(model, name, summary) PATINA_CASE(shader_f64, model, specularLobe(m, N, V, L))
        PATINA_BRDF_MODELS(PATINA_LOBE)
#undef PATINA_LOBE
    }
    return 0.0;
}

ChannelPoint channelPointOf(const MaterialParameters& material) {
    ChannelPoint point;
    point.baseColor = material.baseColor;
    point.roughness = material.roughness;
    point.specular = material.specular;
    point.specularTint = material.specularTint;
    point.specularWeight = material.specularWeight;
    point.iridescence = material.iridescence;
    point.iridescenceIor = material.iridescenceIor;
    point.iridescenceThickness = material.iridescenceThicknessMaximum;
    point.anisotropyStrength = material.anisotropyStrength;
    point.anisotropyRotation = material.anisotropyRotation;
    point.metallic = material.metallic;
    point.clearcoat = material.clearcoat;
    point.clearcoatRoughness = material.clearcoatRoughness;
    point.sheenColor = material.sheenColor;
    point.sheenRoughness = material.sheenRoughness;
    point.transmission = material.transmission;
    point.transmissionAttenuation =
        shader::volumeAttenuation(material.attenuationColor, material.attenuationDistance, material.thickness);
    return point;
}

shader::ChannelInputs gatherChannelInputs(BrdfModelId id, const ChannelPoint& point,
                                          const std::vector<shader::PackedLight>& lights, int asked, int key,
                                          const ChannelEnvironment* environment) {
    switch (id) {
#define PATINA_GATHER(model, name, summary) \
    PATINA_CASE(shader, model, gatherChannelInputs(point, lights, asked, key, environment))
        PATINA_BRDF_MODELS(PATINA_GATHER)
#undef PATINA_GATHER
    }
    return shader::model_Epic::gatherChannelInputs(point, lights, asked, key, environment);
}

}  // namespace patina
