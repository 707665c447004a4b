#pragma once
// Patina's material in glTF's terms, both ways; docs/FORMATS.md ("glTF") derives the mapping.
//   Patina:   F0 = min(0.08 * specular * specularTint, 1) * specularWeight (dielectric),
//             F90 = specularWeight.
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
// pbrMetallicRoughness plus KHR_materials_specular (specularFactor the weight, specularColorFactor
// 0.08 * specular * specularTint / f0FromIor(1.5) = 2 * specular * specularTint) and
// KHR_materials_ior 1.5,
// KHR_materials_clearcoat's factors where the material has a coat (either factor above 0), and
// KHR_materials_sheen's where it has a sheen (its colour or roughness above 0), and
// KHR_materials_transmission's and KHR_materials_volume's where it passes light (the volume
// where it has a thickness), KHR_materials_anisotropy's where its lobe is stretched (a
// strength above 0), and KHR_materials_iridescence's where it has a thin film (a strength above 0).
Json materialToGltf(const Material& material);
extern const char* const kMaterialExtensions[2];   // the extensions materialToGltf always uses
extern const char* const kClearcoatExtension;      // "KHR_materials_clearcoat", where it has a coat
extern const char* const kSheenExtension;          // "KHR_materials_sheen", where it has a sheen
extern const char* const kTransmissionExtension;   // "KHR_materials_transmission", where it has one
extern const char* const kVolumeExtension;         // "KHR_materials_volume", beside a transmission with a thickness
extern const char* const kAnisotropyExtension;     // "KHR_materials_anisotropy", where it has one
extern const char* const kIridescenceExtension;    // "KHR_materials_iridescence", where it has one
// The largest iridescenceIor and film thickness (nm) read: beyond them a file means no film.
inline constexpr double kMaxIridescenceIor = 10.0;
inline constexpr double kMaxIridescenceThickness = 1.0e5;
// The largest |anisotropyRotation| read (radians): a larger one is not an angle a file means, and
// its cosine and sine in fp32 would be noise.
inline constexpr double kMaxAnisotropyRotation = 1.0e4;
// The largest thickness and attenuation distance kept (model units): beyond it a float's
// exponent stays finite and nothing visible changes.
inline constexpr float kMaxThickness = 1.0e6f;

}  // namespace patina::gltf
