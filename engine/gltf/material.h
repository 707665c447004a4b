#pragma once
// Patina's material in glTF's terms, both ways; docs/FORMATS.md ("glTF") derives the mapping.
//   Patina:   F0 = 0.08 * specular (dielectric), F90 = 1.
//   glTF, KHR_materials_ior and KHR_materials_specular (air outside):
//             F0 = min(((ior - 1) / (ior + 1))^2 * specularColorFactor, 1) * specularFactor,
//             F90 = specularFactor.
#include <string>

#include <tiny_gltf.h>

#include "io/json_reader.h"
#include "scene/material.h"

namespace patina::gltf {

constexpr double kExportIor = 1.5;        // glTF's own default: F0 = 0.04

// ((ior - 1) / (ior + 1))^2: normal-incidence reflectance against air.
double f0FromIor(double ior);

// `what` is its JSON pointer ("/materials/0"); values outside [0, 1] are clamped; a value of
// the wrong type or an ior below 1 throws InputError("SOURCE: WHAT/...: ...").
// `fallbackName` names a material that has no name.
Material materialFromGltf(const tinygltf::Material& material, const std::string& what,
                          const std::string& source, const std::string& fallbackName);
// What of KHR_materials_specular and KHR_materials_ior the material above cannot show, said for
// a note ("" when nothing is lost): a specularColorFactor of several colours (drawn grey, at its
// largest channel), an F0 above 0.08 (an ior above about 1.79: drawn as 0.08), a specularFactor
// below 1 (glTF lowers F90 with it; Patina's stays 1), and the two maps (not read). The values
// are read and checked as materialFromGltf reads them (`what`, `source` as there).
std::string specularNotShown(const tinygltf::Material& material, const std::string& what, const std::string& source);

// pbrMetallicRoughness plus KHR_materials_specular (specularFactor 1, so that F90 stays 1, and
// specularColorFactor 0.08 * specular / f0FromIor(1.5) = 2 * specular) and KHR_materials_ior 1.5,
// KHR_materials_clearcoat's factors where the material has a coat (either factor above 0), and
// KHR_materials_sheen's where it has a sheen (its colour or roughness above 0), and
// KHR_materials_transmission's and KHR_materials_volume's where it passes light (the volume
// where it has a thickness), and KHR_materials_anisotropy's where its lobe is stretched (a
// strength above 0).
Json materialToGltf(const Material& material);
extern const char* const kMaterialExtensions[2];   // the extensions materialToGltf always uses
extern const char* const kClearcoatExtension;      // "KHR_materials_clearcoat", where it has a coat
extern const char* const kSheenExtension;          // "KHR_materials_sheen", where it has a sheen
extern const char* const kTransmissionExtension;   // "KHR_materials_transmission", where it has one
extern const char* const kVolumeExtension;         // "KHR_materials_volume", beside a transmission with a thickness
extern const char* const kAnisotropyExtension;     // "KHR_materials_anisotropy", where it has one
// The largest |anisotropyRotation| read (radians): a larger one is not an angle a file means, and
// its cosine and sine in fp32 would be noise.
inline constexpr double kMaxAnisotropyRotation = 1.0e4;
// The largest thickness and attenuation distance kept (model units): beyond it a float's
// exponent stays finite and nothing visible changes.
inline constexpr float kMaxThickness = 1.0e6f;

}  // namespace patina::gltf
