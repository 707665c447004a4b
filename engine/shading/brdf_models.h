#pragma once
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>

#include "shading/brdf_model_id.h"
#include "shading/material_parameters.h"
#include "shading/shading.h"

namespace patina {

constexpr size_t brdfModelCount() {
#define PATINA_MODEL_COUNT(id, name, summary) +1
    return 0 PATINA_BRDF_MODELS(PATINA_MODEL_COUNT);
#undef PATINA_MODEL_COUNT
}

struct BrdfTerms {
    int d, v, f, fd, ms;
};

struct BrdfModelInfo {
    BrdfModelId id;
    std::string_view name;
    BrdfTerms terms;
    std::string_view summary;
    // Single scattering with exact Smith visibility under lights: its white-furnace albedo must
    // stay <= 1. Fdez-Aguera's term acts under an environment only; fresnel_mix's diffuse takes
    // only what the specular leaves.
    bool energyConserving() const {
        return (terms.v == PATINA_V_SMITH_SEPARABLE || terms.v == PATINA_V_SMITH_CORRELATED) &&
               !multipleScattering() &&
               (terms.fd == PATINA_FD_LAMBERT || terms.fd == PATINA_FD_LAMBERT_FRESNEL_MIX);
    }
    // The BRDF itself compensates (Turquin 2019: every light, from the energy table).
    bool multipleScattering() const { return terms.ms == PATINA_MS_TURQUIN; }
    // The split sum adds Fdez-Aguera 2019's multiple scattering (the environment only).
    bool environmentMultipleScattering() const { return terms.ms == PATINA_MS_FDEZ_AGUERA; }
};

std::span<const BrdfModelInfo> brdfModels();
const BrdfModelInfo& brdfModel(BrdfModelId id);
std::optional<BrdfModelId> brdfModelFromName(std::string_view name);
// "epic, epic-standard-d, ...": for messages.
std::string brdfModelNames();
// The GLSL defines that compile this model's permutation, e.g. {"PATINA_V 3", ...}.
std::vector<std::string> brdfModelDefines(BrdfModelId id);

// The model's BRDF on the CPU, fp32: the very GLSL of shaders/shared/brdf_model.glsl compiled for it.
shader::BrdfValue evaluateBrdf(BrdfModelId id, const shader::SurfaceMaterial& material, glm::vec3 N,
                               glm::vec3 V, glm::vec3 L);
shader::SpecularTerms specularTerms(BrdfModelId id, const shader::SurfaceMaterial& material, glm::vec3 N,
                                    glm::vec3 V, glm::vec3 L);
glm::vec3 shadeLight(BrdfModelId id, const shader::PackedLight& light, const shader::SurfaceMaterial& material,
                     glm::vec3 P, glm::vec3 N, glm::vec3 V);
// A packed sphere or tube light by the variant `method` (shadeLight takes the renderer's).
glm::vec3 shadeAreaLight(BrdfModelId id, const shader::PackedLight& light, shader::AreaLightMethod method,
                         const shader::SurfaceMaterial& material, glm::vec3 P, glm::vec3 N, glm::vec3 V);

// The same in double precision (engine/shading/shading_f64.h): the guarded code without fp32 rounding.
struct BrdfValueF64 {
    glm::dvec3 diffuse;
    glm::dvec3 specular;
};
BrdfValueF64 evaluateBrdfF64(BrdfModelId id, const MaterialParameters& material, glm::dvec3 N, glm::dvec3 V,
                             glm::dvec3 L);
// f * NoL with every operation in emulated binary16 (engine/shading/half.h): the fp16 precision row.
glm::dvec3 reflectedF16(BrdfModelId id, const MaterialParameters& material, glm::dvec3 N, glm::dvec3 V, glm::dvec3 L);

// D * V of the model's specular lobe (F = 1, no compensation), double: what the white furnace
// and the energy table integrate.
double specularLobeF64(BrdfModelId id, double roughness, glm::dvec3 N, glm::dvec3 V, glm::dvec3 L);

}  // namespace patina
