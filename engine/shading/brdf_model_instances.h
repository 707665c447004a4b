// Every model of PATINA_BRDF_MODELS through brdf_model_instance.h. No include guard: included
// once per precision by brdf_models.cpp. (The preprocessor cannot loop over the X-macro list
// with an #include, hence one line pair per model.)
#define PATINA_INLINE inline
// A permutation uses only some parameters of each dispatch function (Lambert ignores the angles).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-parameter"
#define PATINA_INSTANCE Epic
#include "shading/brdf_model_instance.h"
#define PATINA_INSTANCE EpicStandardD
#include "shading/brdf_model_instance.h"
#define PATINA_INSTANCE SchlickAlphaHalf
#include "shading/brdf_model_instance.h"
#define PATINA_INSTANCE SmithSeparable
#include "shading/brdf_model_instance.h"
#define PATINA_INSTANCE SmithCorrelated
#include "shading/brdf_model_instance.h"
#define PATINA_INSTANCE Hammon
#include "shading/brdf_model_instance.h"
#define PATINA_INSTANCE SchlickPow5
#include "shading/brdf_model_instance.h"
#define PATINA_INSTANCE ExactFresnel
#include "shading/brdf_model_instance.h"
#define PATINA_INSTANCE Burley
#include "shading/brdf_model_instance.h"
#define PATINA_INSTANCE EpicMultiScatter
#include "shading/brdf_model_instance.h"
#define PATINA_INSTANCE Filament
#include "shading/brdf_model_instance.h"
#define PATINA_INSTANCE Reference
#include "shading/brdf_model_instance.h"
#define PATINA_INSTANCE Gltf
#include "shading/brdf_model_instance.h"
#define PATINA_INSTANCE GltfSingle
#include "shading/brdf_model_instance.h"
#pragma GCC diagnostic pop
#undef PATINA_INLINE
