#pragma once
// glTF materials (glTF 2.0 section 3.9) as ModelMaterials, with their textures and samplers
// (section 3.8) and KHR_texture_transform; the factors mapped as material.h says.
#include <string>
#include <vector>

#include <tiny_gltf.h>

#include "gltf/spec_gloss.h"
#include "model/model.h"

namespace patina::gltf {

// Every material of the document. A slot's `image` is the glTF image index here, for
// model_import.cpp to map once the images are decoded. A texture whose image is only in
// KHR_texture_basisu, EXT_texture_webp or MSFT_texture_dds adds a note to `notes` and leaves its
// slot empty (the factor alone). Throws InputError for an index out of range, a texCoord other
// than 0 or 1, a sampler value or alpha mode glTF does not define, or a value of the wrong type.
// `specGloss`, where given, gets each material with KHR_materials_pbrSpecularGlossiness, whose
// slots then hold its diffuse and specular-glossiness maps until convertSpecularGlossiness.
std::vector<ModelMaterial> modelMaterials(const tinygltf::Model& document, const std::string& source,
                                          std::vector<std::string>& notes,
                                          std::vector<SpecGlossMaterial>* specGloss = nullptr);

}  // namespace patina::gltf
