// Every model of PATINA_BRDF_MODELS through brdf_model_instance.h. No include guard: included
// once per precision by brdf_models.cpp. (The preprocessor cannot loop over the X-macro list
// with an #include, hence one line pair per model.)
#define PATINA_INLINE inline
// A permutation uses only some parameters of each dispatch function (Lambert ignores the angles).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-parameter"
#define PATINA_INSTANCE Epic
#include "brdf_model_instance.h"
#define PATINA_INSTANCE EpicStandardD
#include "brdf_model_instance.h"
#define PATINA_INSTANCE SchlickAlphaHalf
#include "brdf_model_instance.h"
#define PATINA_INSTANCE SmithSeparable
#include "brdf_model_instance.h"
#define PATINA_INSTANCE SmithCorrelated
#include "brdf_model_instance.h"
#define PATINA_INSTANCE Hammon
#include "brdf_model_instance.h"
#define PATINA_INSTANCE SchlickPow5
#include "brdf_model_instance.h"
#define PATINA_INSTANCE ExactFresnel
#include "brdf_model_instance.h"
#define PATINA_INSTANCE Burley
#include "brdf_model_instance.h"
#define PATINA_INSTANCE EpicMultiScatter
#include "brdf_model_instance.h"
#define PATINA_INSTANCE Filament
#include "brdf_model_instance.h"
#define PATINA_INSTANCE Reference
#include "brdf_model_instance.h"
#pragma GCC diagnostic pop
#undef PATINA_INLINE
