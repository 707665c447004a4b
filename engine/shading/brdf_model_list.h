#pragma once
// Patina's named BRDF models: which term each uses (shaders/shared/brdf_model.glsl's PATINA_D, _V, _F,
// _FD, _MS). One list, read by the runtime registry (brdf_models.cpp), the C++ permutations
// (brdf_model_instance.h) and the GLSL defines.
//                                   D  V  F  FD MS
#define PATINA_TERMS_Epic             0, 0, 0, 0, 0
#define PATINA_TERMS_EpicStandardD    1, 0, 0, 0, 0
#define PATINA_TERMS_SchlickAlphaHalf 0, 1, 0, 0, 0
#define PATINA_TERMS_SmithSeparable   0, 2, 0, 0, 0
#define PATINA_TERMS_SmithCorrelated  0, 3, 0, 0, 0
#define PATINA_TERMS_Hammon           0, 4, 0, 0, 0
#define PATINA_TERMS_SchlickPow5      0, 0, 1, 0, 0
#define PATINA_TERMS_ExactFresnel     0, 0, 2, 0, 0
#define PATINA_TERMS_Burley           0, 0, 0, 1, 0
#define PATINA_TERMS_EpicMultiScatter 0, 0, 0, 0, 1
#define PATINA_TERMS_Filament         0, 4, 1, 0, 1
#define PATINA_TERMS_Reference        0, 3, 2, 0, 1

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
    X(Reference, "reference", "exact height-correlated Smith, exact Fresnel, energy compensation")

#define PATINA_TERM_D(d, v, f, fd, ms) d
#define PATINA_TERM_V(d, v, f, fd, ms) v
#define PATINA_TERM_F(d, v, f, fd, ms) f
#define PATINA_TERM_FD(d, v, f, fd, ms) fd
#define PATINA_TERM_MS(d, v, f, fd, ms) ms
#define PATINA_APPLY(macro, args) macro args
#define PATINA_CONCAT(a, b) a##b
#define PATINA_TERMS_OF(id) PATINA_CONCAT(PATINA_TERMS_, id)
#define PATINA_MODEL_NAMESPACE(id) PATINA_CONCAT(model_, id)
