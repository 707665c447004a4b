// The terms a BRDF model chooses (brdf_model.glsl's PATINA_D, PATINA_V, PATINA_F, PATINA_FD,
// PATINA_MS), by name. Shared GLSL / C++ preprocessor constants: brdf_model.glsl tests them and
// engine/shading/brdf_model_list.h builds the models from them.
// D: the distribution.
#define PATINA_D_GGX 0                 // GGX in Lagrange's form, guarded (Karis 2013 eq. 3)
#define PATINA_D_GGX_STANDARD 1        // GGX in its standard form (fp32 cancellation near NoH = 1)
// V: the visibility (geometry over 4 NoL NoV).
#define PATINA_V_SCHLICK_KARIS 0       // Schlick-GGX, k = (r+1)^2/8 (Karis 2013 eq. 4)
#define PATINA_V_SCHLICK_ALPHA_HALF 1  // Schlick-GGX, k = alpha/2
#define PATINA_V_SMITH_SEPARABLE 2     // exact separable Smith GGX (Walter 2007)
#define PATINA_V_SMITH_CORRELATED 3    // exact height-correlated Smith GGX (Heitz 2014)
#define PATINA_V_HAMMON 4              // Hammon 2017's height-correlated approximation
// F: the Fresnel term.
#define PATINA_F_SCHLICK_SG 0          // Schlick, spherical-Gaussian exponent (Karis 2013 eq. 5)
#define PATINA_F_SCHLICK_POW5 1        // Schlick 1994, (1 - VoH)^5
#define PATINA_F_DIELECTRIC_EXACT 2    // the exact dielectric Fresnel from F0
// FD: the diffuse term.
#define PATINA_FD_LAMBERT 0            // c_diff / pi (Karis 2013 eq. 1)
#define PATINA_FD_BURLEY 1             // Burley 2012
#define PATINA_FD_LAMBERT_FRESNEL_MIX 2  // Lambert times 1 - F of the dielectric (glTF 2.0 Appendix B)
// MS: multiple scattering.
#define PATINA_MS_NONE 0               // single scattering
#define PATINA_MS_TURQUIN 1            // Turquin 2019 energy compensation
#define PATINA_MS_FDEZ_AGUERA 2        // Fdez-Aguera 2019, under an environment only (the split sum)
