#pragma once
#include "shading/brdf_model_list.h"

namespace patina {

// A named BRDF model (brdf_model_list.h); engine/shading/brdf_models.h says what each one is.
enum class BrdfModelId {
#define PATINA_MODEL_ENUM(id, name, summary) id,
    PATINA_BRDF_MODELS(PATINA_MODEL_ENUM)
#undef PATINA_MODEL_ENUM
};

}  // namespace patina
