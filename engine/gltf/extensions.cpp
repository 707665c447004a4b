#include "gltf/extensions.h"

#include <algorithm>
#include <iterator>

#include "files/input_error.h"

namespace patina::gltf {

namespace {

struct KnownExtension {
    const char* name;
    ExtensionSupport support;
    const char* effect;
};

// The extensions Patina knows (the Khronos and EXT registries), what it draws of each. A file
// that only lists an extension it does not draw opens as its core glTF says; one that requires
// it does not open (refuseUndrawnRequired).
constexpr KnownExtension kKnown[] = {
    {"KHR_materials_specular", ExtensionSupport::Drawn,
     "the dielectric's F0 colour and Fresnel weight (F90), and their maps"},
    {"KHR_materials_ior", ExtensionSupport::Drawn, "the dielectric's F0 from the index of refraction"},
    {"KHR_materials_iridescence", ExtensionSupport::Drawn, "a thin film's interference colours, and its maps"},
    {"KHR_materials_emissive_strength", ExtensionSupport::Drawn, "emission brighter than 1"},
    {"KHR_texture_transform", ExtensionSupport::Drawn, "the maps' offset, rotation, scale and UV set"},
    {"KHR_xmp_json_ld", ExtensionSupport::Metadata, "metadata (licence, authors); nothing to draw"},
    {"KHR_xmp", ExtensionSupport::Metadata, "metadata; nothing to draw"},
    {"KHR_materials_clearcoat", ExtensionSupport::Drawn,
     "the clear coat, its roughness and normal maps, over the base as the extension layers it"},
    {"KHR_materials_sheen", ExtensionSupport::Drawn,
     "the sheen's colour, roughness and their maps, over the base as the extension layers it"},
    {"KHR_materials_transmission", ExtensionSupport::Drawn,
     "thin-walled: the environment, the lights and the scene's opaque parts behind seen through, "
     "blurred by roughness, and the transmission map"},
    {"KHR_materials_diffuse_transmission", ExtensionSupport::NotDrawn,
     "light through the surface is left out; the material shows opaque"},
    {"KHR_materials_volume", ExtensionSupport::Drawn,
     "Beer-Lambert attenuation over the thickness and its map, thin-walled (no refraction)"},
    {"KHR_materials_anisotropy", ExtensionSupport::Drawn,
     "the strength and rotation stretch the highlights along the tangents, with the anisotropy map"},
    {"KHR_materials_dispersion", ExtensionSupport::NotDrawn, "dispersion is left out"},
    {"KHR_materials_unlit", ExtensionSupport::NotDrawn, "the material is lit, as its metallic-roughness fallback"},
    {"KHR_materials_pbrSpecularGlossiness", ExtensionSupport::Drawn,
     "converted to metallic-roughness by the Khronos conversion (a note names each material)"},
    {"KHR_materials_variants", ExtensionSupport::NotDrawn, "only the default materials are shown"},
    {"KHR_lights_punctual", ExtensionSupport::NotDrawn, "the file's lights are not used; Patina's light rig lights it"},
    {"KHR_animation_pointer", ExtensionSupport::NotDrawn, "animation is not played"},
    {"KHR_draco_mesh_compression", ExtensionSupport::Drawn,
     "Draco-compressed meshes decoded (libdraco); an uncompressed fallback is not read"},
    {"EXT_meshopt_compression", ExtensionSupport::Drawn,
     "meshopt-compressed buffer views decoded (libmeshoptimizer), their filters applied"},
    {"KHR_mesh_quantization", ExtensionSupport::Drawn,
     "8- and 16-bit integer positions, normals, tangents and texture coordinates read"},
    {"EXT_mesh_gpu_instancing", ExtensionSupport::NotDrawn, "each mesh is drawn once, at its node, without its instances"},
    {"KHR_texture_basisu", ExtensionSupport::NotDrawn,
     "KTX2 images are not decoded; a texture's fallback image is used where it has one"},
    {"EXT_texture_webp", ExtensionSupport::Drawn, "WebP images decoded (libwebp) in place of the fallback"},
    {"MSFT_texture_dds", ExtensionSupport::NotDrawn,
     "DDS images are not decoded; a texture's fallback image is used where it has one"},
    {"MSFT_lod", ExtensionSupport::NotDrawn, "only the most detailed level is drawn"},
};

const char* supportName(ExtensionSupport support) {
    switch (support) {
    case ExtensionSupport::Drawn: return "drawn";
    case ExtensionSupport::Metadata: return "metadata";
    case ExtensionSupport::NotDrawn: return "not drawn";
    case ExtensionSupport::Unknown: break;
    }
    return "unknown to Patina";
}

}  // namespace

ModelExtension modelExtension(const std::string& name, bool required) {
    const auto* known = std::find_if(std::begin(kKnown), std::end(kKnown),
                                     [&](const KnownExtension& extension) { return name == extension.name; });
    if (known == std::end(kKnown)) {
        return {name, required, ExtensionSupport::Unknown, "whatever it adds is left out"};
    }
    return {name, required, known->support, known->effect};
}

std::vector<ModelExtension> modelExtensions(const std::vector<std::string>& used,
                                            const std::vector<std::string>& required) {
    std::vector<std::string> names = used;
    for (const std::string& name : required) {   // a file must list these in both; not all do
        if (std::find(names.begin(), names.end(), name) == names.end()) {
            names.push_back(name);
        }
    }
    std::vector<ModelExtension> extensions;
    for (const std::string& name : names) {
        const bool isRequired = std::find(required.begin(), required.end(), name) != required.end();
        extensions.push_back(modelExtension(name, isRequired));
    }
    return extensions;
}

std::string extensionLine(const ModelExtension& extension) {
    return extension.name + (extension.required ? " (required, " : " (") + supportName(extension.support) +
           "): " + extension.effect;
}

void refuseUndrawnRequired(const std::vector<std::string>& required, const std::string& source) {
    for (const std::string& name : required) {
        const ModelExtension extension = modelExtension(name, true);
        if (extension.support == ExtensionSupport::Drawn || extension.support == ExtensionSupport::Metadata) {
            continue;
        }
        // The effect's first clause says what is missing ("Draco-compressed meshes are not decoded").
        const std::string missing = extension.effect.substr(0, extension.effect.find(';'));
        throw InputError(source + ": requires the extension " + name + ", which Patina does not draw (" + missing +
                         "); the file cannot be shown without it");
    }
}

}  // namespace patina::gltf
