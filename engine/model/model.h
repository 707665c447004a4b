#pragma once
// A loaded model: its primitives, materials, images and where each primitive is drawn (glTF 2.0
// sections 3.5-3.9). What the assets layer loads and the renderer draws; the scene document
// names the file and holds the user's edits, never this.
#include <array>
#include <cstdint>
#include <type_traits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "geometry/mesh.h"
#include "shading/material_parameters.h"
#include "shading/texture.h"

namespace patina {

// Decoded pixels as the file holds them: 8-bit RGBA, rows top first. Whether they are sRGB
// depends on the map that uses them (base colour and emissive are; the others are data).
struct ModelImage {
    std::string name;   // the URI, the image's name, or "image N": what a note calls it
    int width = 0, height = 0;
    std::vector<uint8_t> rgba;
};

// One texture reference of a material (glTF textureInfo): an image, how it is sampled, which
// UV set and the KHR_texture_transform. `image` < 0: the material has no such map.
struct TextureSlot {
    int image = -1;
    int texCoord = 0;   // 0 or 1 (after the transform's override)
    TextureSampler sampler;
    TextureTransform transform;
    bool present() const { return image >= 0; }
    bool operator==(const TextureSlot&) const = default;
};

enum class AlphaMode { Opaque, Mask, Blend };

// A glTF metallic-roughness material in Patina's terms (docs/FORMATS.md, "glTF"): the factors
// as Patina's parameters (base colour linear, roughness perceptual, specular from
// KHR_materials_specular / _ior) and each map, multiplied in as the glTF spec says.
struct ModelMaterial {
    std::string name;
    MaterialParameters factors;
    float baseAlpha = 1.0f;                 // baseColorFactor's alpha
    TextureSlot baseColor;                  // sRGB; RGBA multiplies the factor
    TextureSlot metallicRoughness;          // linear; G scales roughness, B metallic
    TextureSlot normal;                     // linear; tangent space, +Y up the bitangent
    float normalScale = 1.0f;
    TextureSlot occlusion;                  // linear; R, on indirect light only
    float occlusionStrength = 1.0f;
    TextureSlot emissive;                   // sRGB
    glm::vec3 emissiveFactor{0.0f};         // times KHR_materials_emissive_strength
    // KHR_materials_clearcoat's maps (its factors are `factors.clearcoat` and
    // `factors.clearcoatRoughness`): R scales the coat, G its roughness; the coat's own normal
    // map (tangent space as `normal`), else the coat follows the geometric normal.
    TextureSlot clearcoat;                  // linear; R
    TextureSlot clearcoatRoughness;         // linear; G
    TextureSlot clearcoatNormal;            // linear
    float clearcoatNormalScale = 1.0f;
    // KHR_materials_sheen's maps (its factors are `factors.sheenColor` and
    // `factors.sheenRoughness`): RGB scales the sheen's colour, A its roughness.
    TextureSlot sheenColor;                 // sRGB; RGB
    TextureSlot sheenRoughness;             // linear; A
    // KHR_materials_transmission's map (R scales `factors.transmission`) and KHR_materials_volume's
    // (G scales `factors.thickness`), drawn where the material transmits (docs/SHADING.md S7).
    TextureSlot transmissionMap;            // linear; R
    TextureSlot thicknessMap;               // linear; G
    // KHR_materials_anisotropy's map (RG the direction in tangent space in [-1, 1], turned by
    // `factors.anisotropyRotation`; B scales `factors.anisotropyStrength`; docs/SHADING.md S8).
    TextureSlot anisotropyMap;              // linear; RGB
    // KHR_materials_specular's maps (its factors are `factors.specularTint` and
    // `factors.specularWeight`): RGB scales the tint, A the weight (docs/SHADING.md S9).
    TextureSlot specularColor;              // sRGB; RGB
    TextureSlot specular;                   // linear; A
    // KHR_materials_iridescence's maps (its factors are `factors.iridescence` and the thickness
    // range): R scales the strength, G places the thickness between minimum and maximum.
    TextureSlot iridescenceMap;             // linear; R
    TextureSlot iridescenceThickness;       // linear; G
    AlphaMode alphaMode = AlphaMode::Opaque;
    float alphaCutoff = 0.5f;
    bool doubleSided = false;
    bool operator==(const ModelMaterial&) const = default;
};

// A material's maps in their one order (the shaders' too: surface_maps.glsl): glTF 2.0's five,
// then KHR_materials_clearcoat's three, KHR_materials_sheen's two, KHR_materials_transmission's
// and KHR_materials_volume's one each, KHR_materials_specular's two, KHR_materials_iridescence's
// two, KHR_materials_anisotropy's one; each with whether its
// texels are sRGB (base colour, emissive, sheen colour and specular colour; the others are data,
// glTF 2.0 3.9.2-3.9.3), its name for people and its key
// (glTF's name of the property, which scene files use too).
template <typename Slot>
struct MapOf {
    Slot* slot;
    bool srgb;
    const char* name;
    const char* key;
};
inline constexpr int kCoreMapCount = 5;   // glTF 2.0's own maps, the first of mapsOf
inline constexpr int kMapCount = 17;
template <typename Material>   // ModelMaterial or const ModelMaterial
auto mapsOf(Material& material) {
    using Slot = std::conditional_t<std::is_const_v<Material>, const TextureSlot, TextureSlot>;
    return std::array<MapOf<Slot>, kMapCount>{
        {{&material.baseColor, true, "base colour", "baseColorTexture"},
         {&material.metallicRoughness, false, "metallic-roughness", "metallicRoughnessTexture"},
         {&material.normal, false, "normal", "normalTexture"},
         {&material.occlusion, false, "occlusion", "occlusionTexture"},
         {&material.emissive, true, "emissive", "emissiveTexture"},
         {&material.clearcoat, false, "clear coat", "clearcoatTexture"},
         {&material.clearcoatRoughness, false, "clear coat roughness", "clearcoatRoughnessTexture"},
         {&material.clearcoatNormal, false, "clear coat normal", "clearcoatNormalTexture"},
         {&material.sheenColor, true, "sheen colour", "sheenColorTexture"},
         {&material.sheenRoughness, false, "sheen roughness", "sheenRoughnessTexture"},
         {&material.transmissionMap, false, "transmission", "transmissionTexture"},
         {&material.thicknessMap, false, "thickness", "thicknessTexture"},
         {&material.specularColor, true, "specular colour", "specularColorTexture"},
         {&material.specular, false, "specular", "specularTexture"},
         {&material.iridescenceMap, false, "iridescence", "iridescenceTexture"},
         {&material.iridescenceThickness, false, "iridescence thickness", "iridescenceThicknessTexture"},
         {&material.anisotropyMap, false, "anisotropy", "anisotropyTexture"}}};
}
// The map of `material` whose key is `key`, or nothing: what a scene file's key names.
template <typename Material>
auto mapWithKey(Material& material, std::string_view key) -> std::optional<typename decltype(mapsOf(material))::value_type> {
    for (const auto& map : mapsOf(material)) {
        if (key == map.key) {
            return map;
        }
    }
    return std::nullopt;
}

// Whether KHR_materials_specular's maps are drawn for `material`: either one compiles the tint
// and weight in (PATINA_SPECULAR), whatever the factors they scale.
inline bool hasSpecularMaps(const ModelMaterial& material) {
    return material.specularColor.present() || material.specular.present();
}

// One primitive placed once: glTF node world matrix times the mesh's primitive. `material` < 0
// draws glTF's default material (white, metallic 1, roughness 1).
// Primitives are shared between draws and wound counter-clockwise in their own space; a
// transform with a negative determinant winds them clockwise in world space (glTF 2.0 section
// 3.7.4). Such a draw has `mirrored` set, and whoever draws it takes clockwise triangles as its
// front faces (glFrontFace(GL_CW)); its normals go through the inverse transpose as any draw's.
struct DrawItem {
    int primitive = 0;
    int material = -1;
    glm::mat4 transform{1.0f};
    std::string node;        // the node's name (or "node N"), for picking and messages
    bool mirrored = false;   // determinant(transform) < 0
    bool operator==(const DrawItem&) const = default;
};

// A camera of the file as a node of the default scene places it (glTF 2.0 section 3.10): from
// the node's origin it looks down the node's -Z with the node's +Y up. The node's scale is not
// the camera's: only the directions are kept, as unit vectors.
struct ModelCamera {
    std::string name;     // the camera's name, else its node's, else "camera N"
    std::string node;     // the node placing it (its name or "node N")
    int index = 0;        // N: its place in the file's `cameras`
    bool perspective = true;   // false: orthographic, which Patina does not draw
    float yfov = 0.8f;         // perspective: the vertical field of view, radians
    glm::vec3 position{0.0f};
    glm::vec3 forward{0.0f, 0.0f, -1.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    bool operator==(const ModelCamera&) const = default;
};

// An extension the file uses (glTF 2.0 section 3.12) and what Patina draws of it.
enum class ExtensionSupport {
    Drawn,      // shaded or read as its specification says
    Metadata,   // nothing in it changes the picture (a licence, a document's history)
    NotDrawn,   // known, but what it adds is left out: the picture differs from the file's
    Unknown,    // not known to Patina: whatever it adds is left out
};
struct ModelExtension {
    std::string name;
    bool required = false;   // in extensionsRequired
    ExtensionSupport support = ExtensionSupport::Unknown;
    std::string effect;      // what Patina shows of it, for people
    bool operator==(const ModelExtension&) const = default;
};

struct Model {
    std::vector<Mesh> primitives;        // each in its own (the mesh's) space
    std::vector<ModelMaterial> materials;
    std::vector<ModelImage> images;
    std::vector<DrawItem> draws;         // the default scene's node instances, in node order
    std::vector<ModelCamera> cameras;    // the default scene's camera nodes, in node order
    std::vector<ModelExtension> extensions;   // every extension the file uses, in its order
    std::vector<std::string> notes;      // what was skipped or left out, a line each
};

}  // namespace patina
