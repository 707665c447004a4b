#pragma once
// Patina's named BRDF models: which term each uses (shaders/shared/brdf_model.glsl's PATINA_D, _V, _F,
// _FD, _MS, by the names of brdf_terms.glsl). One list, read by the runtime registry
// (brdf_models.cpp), the C++ permutations (brdf_model_instance.h) and the GLSL defines.
#include "brdf_terms.glsl"

// D, V, F, FD, MS
#define PATINA_TERMS_Epic \
    PATINA_D_GGX, PATINA_V_SCHLICK_KARIS, PATINA_F_SCHLICK_SG, PATINA_FD_LAMBERT, PATINA_MS_NONE
#define PATINA_TERMS_EpicStandardD \
    PATINA_D_GGX_STANDARD, PATINA_V_SCHLICK_KARIS, PATINA_F_SCHLICK_SG, PATINA_FD_LAMBERT, PATINA_MS_NONE
#define PATINA_TERMS_SchlickAlphaHalf \
    PATINA_D_GGX, PATINA_V_SCHLICK_ALPHA_HALF, PATINA_F_SCHLICK_SG, PATINA_FD_LAMBERT, PATINA_MS_NONE
#define PATINA_TERMS_SmithSeparable \
    PATINA_D_GGX, PATINA_V_SMITH_SEPARABLE, PATINA_F_SCHLICK_SG, PATINA_FD_LAMBERT, PATINA_MS_NONE
#define PATINA_TERMS_SmithCorrelated \
    PATINA_D_GGX, PATINA_V_SMITH_CORRELATED, PATINA_F_SCHLICK_SG, PATINA_FD_LAMBERT, PATINA_MS_NONE
#define PATINA_TERMS_Hammon \
    PATINA_D_GGX, PATINA_V_HAMMON, PATINA_F_SCHLICK_SG, PATINA_FD_LAMBERT, PATINA_MS_NONE
#define PATINA_TERMS_SchlickPow5 \
    PATINA_D_GGX, PATINA_V_SCHLICK_KARIS, PATINA_F_SCHLICK_POW5, PATINA_FD_LAMBERT, PATINA_MS_NONE
#define PATINA_TERMS_ExactFresnel \
    PATINA_D_GGX, PATINA_V_SCHLICK_KARIS, PATINA_F_DIELECTRIC_EXACT, PATINA_FD_LAMBERT, PATINA_MS_NONE
#define PATINA_TERMS_Burley \
    PATINA_D_GGX, PATINA_V_SCHLICK_KARIS, PATINA_F_SCHLICK_SG, PATINA_FD_BURLEY, PATINA_MS_NONE
#define PATINA_TERMS_EpicMultiScatter \
    PATINA_D_GGX, PATINA_V_SCHLICK_KARIS, PATINA_F_SCHLICK_SG, PATINA_FD_LAMBERT, PATINA_MS_TURQUIN
#define PATINA_TERMS_Filament \
    PATINA_D_GGX, PATINA_V_HAMMON, PATINA_F_SCHLICK_POW5, PATINA_FD_LAMBERT, PATINA_MS_TURQUIN
#define PATINA_TERMS_Reference \
    PATINA_D_GGX, PATINA_V_SMITH_CORRELATED, PATINA_F_DIELECTRIC_EXACT, PATINA_FD_LAMBERT, PATINA_MS_TURQUIN
#define PATINA_TERMS_Gltf \
    PATINA_D_GGX, PATINA_V_SMITH_CORRELATED, PATINA_F_SCHLICK_POW5, PATINA_FD_LAMBERT_FRESNEL_MIX, PATINA_MS_FDEZ_AGUERA
#define PATINA_TERMS_GltfSingle \
    PATINA_D_GGX, PATINA_V_SMITH_CORRELATED, PATINA_F_SCHLICK_POW5, PATINA_FD_LAMBERT_FRESNEL_MIX, PATINA_MS_NONE

// X(identifier, name, summary)
#define PATINA_BRDF_MODELS(X)                                                                        \
    X(Epic, "epic", "Karis 2013 as specified: GGX, Schlick-GGX k=(r+1)^2/8, SG Fresnel, Lambert")  \
    X(EpicStandardD, "epic-standard-d", "epic with D in its standard form (fp32 cancellation)")   \
    X(SchlickAlphaHalf, "schlick-alpha", "epic with Schlick-GGX k = alpha/2")                      \
    X(SmithSeparable, "smith-separable", "epic with exact separable Smith GGX (Walter 2007)")      \
    X(SmithCorrelated, "smith-correlated", "epic with exact height-correlated Smith (Heitz 2014)") \
    X(Hammon, "hammon", "epic with Hammon 2017's height-correlated approximation")                 \
    X(SchlickPow5, "schlick-pow5", "epic with Schlick's pow5 Fresnel")                             \
    X(ExactFresnel, "exact-fresnel", "epic with exact dielectric Fresnel from F0")                 \
    X(Burley, "burley", "epic with Burley 2012 diffuse")                                           \
    X(EpicMultiScatter, "epic-ms", "epic with Turquin 2019 multiple-scattering compensation")      \
    X(Filament, "filament", "Hammon visibility, pow5 Fresnel, Lambert, energy compensation")      \
    X(Reference, "reference", "exact height-correlated Smith, exact Fresnel, energy compensation")   \
    X(Gltf, "gltf", "glTF 2.0 Appendix B: fresnel_mix, correlated Smith, pow5; Fdez-Aguera under IBL")   \
    X(GltfSingle, "gltf-single", "gltf without Fdez-Aguera's multiple scattering under IBL")

#define PATINA_TERM_D(d, v, f, fd, ms) d
#define PATINA_TERM_V(d, v, f, fd, ms) v
#define PATINA_TERM_F(d, v, f, fd, ms) f
#define PATINA_TERM_FD(d, v, f, fd, ms) fd
#define PATINA_TERM_MS(d, v, f, fd, ms) ms
#define PATINA_APPLY(macro, args) macro args
#define PATINA_CONCAT(a, b) a##b
#define PATINA_TERMS_OF(id) PATINA_CONCAT(PATINA_TERMS_, id)
#define PATINA_MODEL_NAMESPACE(id) PATINA_CONCAT(model_, id)
