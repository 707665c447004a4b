#include "gltf/material.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <tuple>
#include <vector>

#include <glm/vec3.hpp>

#include "gltf/values.h"
#include "files/input_error.h"
#include "shading/shading.h"

namespace patina::gltf {

namespace {

constexpr const char* kSpecular = "KHR_materials_specular";
constexpr const char* kIor = "KHR_materials_ior";
constexpr const char* kClearcoat = "KHR_materials_clearcoat";
constexpr const char* kSheen = "KHR_materials_sheen";
constexpr const char* kTransmission = "KHR_materials_transmission";
constexpr const char* kVolume = "KHR_materials_volume";
constexpr const char* kAnisotropy = "KHR_materials_anisotropy";
constexpr const char* kIridescence = "KHR_materials_iridescence";

float unit(double value) { return float(std::clamp(value, 0.0, 1.0)); }

// Written as the float's exact value, so that reading it back gives the same float.
double exact(float value) { return double(value); }

}  // namespace

const char* const kMaterialExtensions[2] = {kSpecular, kIor};
const char* const kClearcoatExtension = kClearcoat;
const char* const kSheenExtension = kSheen;
const char* const kTransmissionExtension = kTransmission;
const char* const kVolumeExtension = kVolume;
const char* const kAnisotropyExtension = kAnisotropy;
const char* const kIridescenceExtension = kIridescence;

double f0FromIor(double ior) {
    const double r = (ior - 1.0) / (ior + 1.0);
    return r * r;
}

namespace {
// KHR_materials_transmission's transmissionFactor (0 by default: none) and KHR_materials_volume's
// thicknessFactor (0: thin), attenuationColor (white) and attenuationDistance (infinite by
// default, Patina's 0; the schema wants it above 0). Their maps are model_materials.cpp's.
void volumeFromGltf(const tinygltf::Material& material, const std::string& what, const std::string& source,
                    Material& result) {
    const std::string transmissionAt = what + "/extensions/" + kTransmission;
    const tinygltf::Value* transmission = extensionOf(material.extensions, kTransmission);
    result.transmission = unit(numberField(transmission, "transmissionFactor", 0.0, transmissionAt, source));
    const std::string volumeAt = what + "/extensions/" + kVolume;
    const tinygltf::Value* volume = extensionOf(material.extensions, kVolume);
    const double thickness = numberField(volume, "thicknessFactor", 0.0, volumeAt, source);
    if (thickness < 0.0) {
        throw InputError(source + ": " + volumeAt + "/thicknessFactor: " + numberText(thickness) + " is below 0");
    }
    result.thickness = float(std::min(thickness, double(kMaxThickness)));
    const std::vector<double> color = numbersField(volume, "attenuationColor", 3, volumeAt, source);
    for (size_t i = 0; i < color.size(); ++i) {
        result.attenuationColor[int(i)] = unit(color[i]);
    }
    const double distance = numberField(volume, "attenuationDistance", 0.0, volumeAt, source);
    if (volume && volume->Has("attenuationDistance") && !(distance > 0.0)) {
        throw InputError(source + ": " + volumeAt + "/attenuationDistance: " + numberText(distance) +
                         " is not above 0 (leave it out for no attenuation)");
    }
    result.attenuationDistance = float(std::min(distance, double(kMaxThickness)));
}

// KHR_materials_anisotropy's anisotropyStrength (0 by default: none; clamped to [0, 1]) and
// anisotropyRotation (radians, 0 by default; any finite angle, kept as the file has it). Its
// map is model_materials.cpp's.
void anisotropyFromGltf(const tinygltf::Material& material, const std::string& what, const std::string& source,
                        Material& result) {
    const std::string at = what + "/extensions/" + kAnisotropy;
    const tinygltf::Value* anisotropy = extensionOf(material.extensions, kAnisotropy);
    result.anisotropyStrength = unit(numberField(anisotropy, "anisotropyStrength", 0.0, at, source));
    const double rotation = numberField(anisotropy, "anisotropyRotation", 0.0, at, source);
    if (!std::isfinite(rotation) || std::abs(rotation) > kMaxAnisotropyRotation) {
        throw InputError(source + ": " + at + "/anisotropyRotation: " + numberText(rotation) +
                         " is not an angle in radians");
    }
    result.anisotropyRotation = float(rotation);
}

// KHR_materials_iridescence's iridescenceFactor (0 by default: none; clamped to [0, 1]),
// iridescenceIor (1.3; at least 1, the schema's) and the thickness range in nm (100 to 400;
// neither below 0, the schema's; the minimum may exceed the maximum). Its maps are
// model_materials.cpp's.
void iridescenceFromGltf(const tinygltf::Material& material, const std::string& what, const std::string& source,
                         Material& result) {
    const std::string at = what + "/extensions/" + kIridescence;
    const tinygltf::Value* film = extensionOf(material.extensions, kIridescence);
    result.iridescence = unit(numberField(film, "iridescenceFactor", 0.0, at, source));
    const double ior = numberField(film, "iridescenceIor", 1.3, at, source);
    if (!(ior >= 1.0) || ior > kMaxIridescenceIor) {
        throw InputError(source + ": " + at + "/iridescenceIor: " + numberText(ior) + " is not an ior from 1 to " +
                         std::to_string(int(kMaxIridescenceIor)));
    }
    result.iridescenceIor = float(ior);
    for (auto [key, fallback, field] : {std::tuple{"iridescenceThicknessMinimum", 100.0, &result.iridescenceThicknessMinimum},
                                        std::tuple{"iridescenceThicknessMaximum", 400.0, &result.iridescenceThicknessMaximum}}) {
        const double thickness = numberField(film, key, fallback, at, source);
        if (!(thickness >= 0.0) || thickness > kMaxIridescenceThickness) {
            throw InputError(source + ": " + at + "/" + key + ": " + numberText(thickness) +
                             " is not a thickness in nanometres from 0 to " +
                             std::to_string(int(kMaxIridescenceThickness)));
        }
        *field = float(thickness);
    }
}

// KHR_materials_specular's and KHR_materials_ior's factors as the file has them (glTF's defaults
// for what it leaves out), checked; the maps are model_materials.cpp's.
struct GltfSpecular {
    double factor = 1.0;
    glm::dvec3 color{1.0};
    double ior = kExportIor;
};

GltfSpecular specularFromGltf(const tinygltf::Material& material, const std::string& what, const std::string& source) {
    GltfSpecular read;
    const std::string specularAt = what + "/extensions/" + kSpecular;
    const tinygltf::Value* specular = extensionOf(material.extensions, kSpecular);
    read.factor = numberField(specular, "specularFactor", 1.0, specularAt, source);
    const std::vector<double> color = numbersField(specular, "specularColorFactor", 3, specularAt, source);
    if (!color.empty()) {
        read.color = {color[0], color[1], color[2]};
    }
    const std::string iorAt = what + "/extensions/" + kIor;
    read.ior = numberField(extensionOf(material.extensions, kIor), "ior", kExportIor, iorAt, source);
    // 0 is allowed beside 1 and above: KHR_materials_ior's schema keeps it for converting
    // specular-glossiness materials (F0 = 1, the specular colour then F0 itself).
    if (read.ior < 1.0 && read.ior != 0.0) {
        throw InputError(source + ": " + iorAt + "/ior: " + numberText(read.ior) + " is below 1 (and not 0)");
    }
    return read;
}

// The extension's dielectric F0 per channel, min(F0(ior) specularColorFactor, 1), as Patina's
// 0.08 specular tint (shading/material_parameters.h): specular as large as F0's largest channel
// lets it be (up to 1, F0 0.08), the tint the rest (its largest channel 1 up to there); a black
// F0 is specular 0 with no tint. specularFactor is the weight of the Fresnel, F0 and F90 alike.
void specularToPatina(const GltfSpecular& read, Material& result) {
    glm::dvec3 f0;
    for (int c = 0; c < 3; ++c) {
        f0[c] = std::min(f0FromIor(read.ior) * std::max(read.color[c], 0.0), 1.0);
    }
    const double perSpecular = double(shader::F0_PER_SPECULAR);
    const double largest = std::max({f0.r, f0.g, f0.b});
    result.specular = unit(largest / perSpecular);
    result.specularTint = glm::vec3(1.0f);
    if (result.specular > 0.0f) {
        for (int c = 0; c < 3; ++c) {
            result.specularTint[c] = float(f0[c] / (perSpecular * double(result.specular)));
        }
    }
    result.specularWeight = unit(read.factor);
}
}  // namespace

Material materialFromGltf(const tinygltf::Material& material, const std::string& what,
                          const std::string& source, const std::string& fallbackName) {
    const tinygltf::PbrMetallicRoughness& pbr = material.pbrMetallicRoughness;
    Material result;
    result.name = material.name.empty() ? fallbackName : material.name;
    // Shaded as the file's format defines it (glTF 2.0 Appendix B), so that what is tuned here
    // is what a glTF engine shows; a scene may still choose another model per part.
    result.model = BrdfModelId::Gltf;
    for (int i = 0; i < 3; ++i) {
        result.baseColor[i] = unit(pbr.baseColorFactor.at(size_t(i)));
    }
    result.metallic = unit(pbr.metallicFactor);
    result.roughness = unit(pbr.roughnessFactor);

    specularToPatina(specularFromGltf(material, what, source), result);
    // KHR_materials_clearcoat: clearcoatFactor and clearcoatRoughnessFactor, both 0 by default
    // (no coat). Its maps are read beside the core maps (model_materials.cpp).
    const std::string clearcoatAt = what + "/extensions/" + kClearcoat;
    const tinygltf::Value* clearcoat = extensionOf(material.extensions, kClearcoat);
    result.clearcoat = unit(numberField(clearcoat, "clearcoatFactor", 0.0, clearcoatAt, source));
    result.clearcoatRoughness = unit(numberField(clearcoat, "clearcoatRoughnessFactor", 0.0, clearcoatAt, source));
    // KHR_materials_sheen: sheenColorFactor (linear RGB) and sheenRoughnessFactor, both 0 by
    // default (no sheen). Its maps are read beside the core maps (model_materials.cpp).
    const std::string sheenAt = what + "/extensions/" + kSheen;
    const tinygltf::Value* sheen = extensionOf(material.extensions, kSheen);
    const std::vector<double> sheenColor = numbersField(sheen, "sheenColorFactor", 3, sheenAt, source);
    for (size_t i = 0; i < sheenColor.size(); ++i) {
        result.sheenColor[int(i)] = unit(sheenColor[i]);
    }
    result.sheenRoughness = unit(numberField(sheen, "sheenRoughnessFactor", 0.0, sheenAt, source));
    volumeFromGltf(material, what, source, result);
    anisotropyFromGltf(material, what, source, result);
    iridescenceFromGltf(material, what, source, result);
    return result;
}

Json materialToGltf(const Material& material) {
    // specularColorFactor = 0.08 specular tint / F0(ior), per channel, with ior 1.5 (= 2 specular
    // tint). A material that passes light refracts by its ior in other viewers (a volume's): where
    // its F0 is grey and below 1, the ior whose F0 it is, and a white colour factor.
    const glm::dvec3 f0 = double(shader::F0_PER_SPECULAR) * double(material.specular) * glm::dvec3(material.specularTint);
    double ior = kExportIor;
    if (material.transmission > 0.0f && f0.r == f0.g && f0.g == f0.b && f0.r > 0.0 && f0.r < 1.0) {
        ior = (1.0 + std::sqrt(f0.r)) / (1.0 - std::sqrt(f0.r));
    }
    Json color = Json::array();
    for (int c = 0; c < 3; ++c) {
        color.push_back(ior == kExportIor ? exact(float(f0[c] / f0FromIor(kExportIor))) : 1.0);
    }
    const glm::vec3& base = material.baseColor;
    Json json{
        {"name", material.name},
        {"pbrMetallicRoughness",
         {{"baseColorFactor", {exact(base.r), exact(base.g), exact(base.b), 1.0}},
          {"metallicFactor", exact(material.metallic)},
          {"roughnessFactor", exact(material.roughness)}}},
        {"extensions",
         {{kSpecular, {{"specularFactor", exact(material.specularWeight)}, {"specularColorFactor", color}}},
          {kIor, {{"ior", ior}}}}}};
    // A coat only where there is one: a material without keeps the two extensions every export has.
    if (material.clearcoat > 0.0f || material.clearcoatRoughness > 0.0f) {
        json["extensions"][kClearcoat] = {{"clearcoatFactor", exact(material.clearcoat)},
                                          {"clearcoatRoughnessFactor", exact(material.clearcoatRoughness)}};
    }
    // A sheen only where there is one, as the coat.
    if (material.sheenColor != glm::vec3(0.0f) || material.sheenRoughness > 0.0f) {
        const glm::vec3& sheen = material.sheenColor;
        json["extensions"][kSheen] = {{"sheenColorFactor", {exact(sheen.r), exact(sheen.g), exact(sheen.b)}},
                                      {"sheenRoughnessFactor", exact(material.sheenRoughness)}};
    }
    // A transmission only where there is one, and its volume only beside it (the volume
    // extension requires a transmission); an infinite distance (0) is left out, as glTF's default.
    if (material.transmission > 0.0f) {
        json["extensions"][kTransmission] = {{"transmissionFactor", exact(material.transmission)}};
        if (material.thickness > 0.0f) {
            const glm::vec3& c = material.attenuationColor;
            Json volume{{"thicknessFactor", exact(material.thickness)},
                        {"attenuationColor", {exact(c.r), exact(c.g), exact(c.b)}}};
            if (material.attenuationDistance > 0.0f) {
                volume["attenuationDistance"] = exact(material.attenuationDistance);
            }
            json["extensions"][kVolume] = volume;
        }
    }
    // An anisotropy only where there is one (a strength above 0), as the coat.
    if (material.anisotropyStrength > 0.0f) {
        json["extensions"][kAnisotropy] = {{"anisotropyStrength", exact(material.anisotropyStrength)},
                                           {"anisotropyRotation", exact(material.anisotropyRotation)}};
    }
    // A thin film only where there is one (a strength above 0), as the coat.
    if (material.iridescence > 0.0f) {
        json["extensions"][kIridescence] = {
            {"iridescenceFactor", exact(material.iridescence)},
            {"iridescenceIor", exact(material.iridescenceIor)},
            {"iridescenceThicknessMinimum", exact(material.iridescenceThicknessMinimum)},
            {"iridescenceThicknessMaximum", exact(material.iridescenceThicknessMaximum)}};
    }
    return json;
}

}  // namespace patina::gltf
