#include "gltf/json_rules.h"

#include <unordered_map>

namespace patina::gltf {

namespace {

using Rules = std::unordered_map<std::string, JsonRule>;

constexpr JsonRule kObject{JsonKind::Object}, kArray{JsonKind::Array}, kString{JsonKind::String},
    kNumber{JsonKind::Number}, kBoolean{JsonKind::Boolean}, kInteger{JsonKind::Integer},
    kUnsigned{JsonKind::Unsigned};

constexpr JsonRule index(const char* noun) { return {JsonKind::Index, noun}; }

// An array of `element`s at `at`.
void arrayOf(Rules& rules, const std::string& at, JsonRule element) {
    rules[at] = kArray;
    rules[at + "/*"] = element;
}

// A textureInfo (section 5.29, with 5.25's scale and 5.26's strength) and its
// KHR_texture_transform.
void textureInfo(Rules& rules, const std::string& at) {
    rules[at] = kObject;
    rules[at + "/index"] = index("texture");
    rules[at + "/texCoord"] = kInteger;
    rules[at + "/scale"] = kNumber;
    rules[at + "/strength"] = kNumber;
    rules[at + "/extensions"] = kObject;
    const std::string transform = at + "/extensions/KHR_texture_transform";
    rules[transform] = kObject;
    arrayOf(rules, transform + "/offset", kNumber);
    arrayOf(rules, transform + "/scale", kNumber);
    rules[transform + "/rotation"] = kNumber;
    rules[transform + "/texCoord"] = kInteger;
}

void materials(Rules& rules) {
    const std::string m = "/materials/*", pbr = m + "/pbrMetallicRoughness";
    rules[m + "/name"] = kString;
    rules[pbr] = kObject;
    arrayOf(rules, pbr + "/baseColorFactor", kNumber);
    rules[pbr + "/metallicFactor"] = kNumber;
    rules[pbr + "/roughnessFactor"] = kNumber;
    for (const std::string& texture : {pbr + "/baseColorTexture", pbr + "/metallicRoughnessTexture",
                                       m + "/normalTexture", m + "/occlusionTexture", m + "/emissiveTexture"}) {
        textureInfo(rules, texture);
    }
    arrayOf(rules, m + "/emissiveFactor", kNumber);
    rules[m + "/alphaMode"] = kString;
    rules[m + "/alphaCutoff"] = kNumber;
    rules[m + "/doubleSided"] = kBoolean;
    const std::string extensions = m + "/extensions";
    rules[extensions] = kObject;
    rules[extensions + "/KHR_materials_emissive_strength"] = kObject;
    rules[extensions + "/KHR_materials_emissive_strength/emissiveStrength"] = kNumber;
    rules[extensions + "/KHR_materials_specular"] = kObject;
    rules[extensions + "/KHR_materials_specular/specularFactor"] = kNumber;
    arrayOf(rules, extensions + "/KHR_materials_specular/specularColorFactor", kNumber);
    rules[extensions + "/KHR_materials_ior"] = kObject;
    rules[extensions + "/KHR_materials_ior/ior"] = kNumber;
    const std::string specGloss = extensions + "/KHR_materials_pbrSpecularGlossiness";
    rules[specGloss] = kObject;
    arrayOf(rules, specGloss + "/diffuseFactor", kNumber);
    arrayOf(rules, specGloss + "/specularFactor", kNumber);
    rules[specGloss + "/glossinessFactor"] = kNumber;
    textureInfo(rules, specGloss + "/diffuseTexture");
    textureInfo(rules, specGloss + "/specularGlossinessTexture");
}

void textures(Rules& rules) {
    rules["/textures/*/source"] = index("image");
    rules["/textures/*/sampler"] = index("sampler");
    rules["/textures/*/extensions"] = kObject;
    for (const char* other : {"KHR_texture_basisu", "EXT_texture_webp", "MSFT_texture_dds"}) {
        rules[std::string("/textures/*/extensions/") + other] = kObject;
    }
    rules["/textures/*/extensions/EXT_texture_webp/source"] = index("image");
    for (const char* filter : {"magFilter", "minFilter", "wrapS", "wrapT"}) {
        rules[std::string("/samplers/*/") + filter] = kInteger;
    }
    rules["/images/*/uri"] = kString;
    rules["/images/*/mimeType"] = kString;
    rules["/images/*/bufferView"] = index("buffer view");
    rules["/images/*/name"] = kString;
}

// Scenes, nodes and meshes (sections 5.17, 5.19, 5.23 and 5.24).
void sceneGraph(Rules& rules) {
    rules["/scene"] = index("scene");
    rules["/scenes/*/name"] = kString;
    arrayOf(rules, "/scenes/*/nodes", index("node"));
    arrayOf(rules, "/nodes/*/children", index("node"));
    rules["/nodes/*/mesh"] = index("mesh");
    rules["/nodes/*/camera"] = index("camera");
    rules["/nodes/*/name"] = kString;
    for (const char* transform : {"matrix", "translation", "rotation", "scale"}) {
        arrayOf(rules, std::string("/nodes/*/") + transform, kNumber);
    }
    const std::string primitive = "/meshes/*/primitives/*";
    arrayOf(rules, "/meshes/*/primitives", kObject);
    rules[primitive + "/attributes"] = kObject;
    rules[primitive + "/attributes/{}"] = index("accessor");
    rules[primitive + "/indices"] = index("accessor");
    rules[primitive + "/material"] = index("material");
    rules[primitive + "/mode"] = kInteger;
    rules[primitive + "/extensions"] = kObject;
    const std::string draco = primitive + "/extensions/KHR_draco_mesh_compression";
    rules[draco] = kObject;
    rules[draco + "/bufferView"] = index("buffer view");
    rules[draco + "/attributes"] = kObject;
    rules[draco + "/attributes/{}"] = kUnsigned;   // Draco's own attribute ids
}

// Cameras (sections 5.12-5.14): what a camera node's view is made of.
void cameras(Rules& rules) {
    rules["/cameras/*/name"] = kString;
    rules["/cameras/*/type"] = kString;
    rules["/cameras/*/perspective"] = kObject;
    rules["/cameras/*/perspective/yfov"] = kNumber;
    rules["/cameras/*/orthographic"] = kObject;
}

// Accessors, buffer views and buffers (sections 5.1-5.4, 5.10 and 5.11).
void data(Rules& rules) {
    const std::string a = "/accessors/*", sparse = a + "/sparse";
    rules[a + "/bufferView"] = index("buffer view");
    rules[a + "/byteOffset"] = kUnsigned;
    rules[a + "/componentType"] = kInteger;
    rules[a + "/normalized"] = kBoolean;
    rules[a + "/count"] = kUnsigned;
    rules[a + "/type"] = kString;
    rules[sparse] = kObject;
    rules[sparse + "/count"] = kUnsigned;
    for (const std::string& part : {sparse + "/indices", sparse + "/values"}) {
        rules[part] = kObject;
        rules[part + "/bufferView"] = index("buffer view");
        rules[part + "/byteOffset"] = kUnsigned;
    }
    rules[sparse + "/indices/componentType"] = kInteger;
    rules["/bufferViews/*/buffer"] = index("buffer");
    for (const char* size : {"byteOffset", "byteLength", "byteStride"}) {
        rules[std::string("/bufferViews/*/") + size] = kUnsigned;
    }
    rules["/buffers/*/uri"] = kString;
    rules["/buffers/*/byteLength"] = kUnsigned;
    // EXT_meshopt_compression: a view's compressed stream, and the buffer that only stands in.
    const std::string meshopt = "/bufferViews/*/extensions/EXT_meshopt_compression";
    rules["/bufferViews/*/extensions"] = kObject;
    rules[meshopt] = kObject;
    rules[meshopt + "/buffer"] = index("buffer");
    for (const char* size : {"byteOffset", "byteLength", "byteStride", "count"}) {
        rules[meshopt + "/" + size] = kUnsigned;
    }
    rules[meshopt + "/mode"] = kString;
    rules[meshopt + "/filter"] = kString;
    rules["/buffers/*/extensions"] = kObject;
    rules["/buffers/*/extensions/EXT_meshopt_compression"] = kObject;
    rules["/buffers/*/extensions/EXT_meshopt_compression/fallback"] = kBoolean;
}

Rules makeRules() {
    Rules rules;
    for (const char* collection : {"/scenes", "/nodes", "/meshes", "/materials", "/textures", "/images", "/samplers",
                                   "/accessors", "/bufferViews", "/buffers", "/cameras"}) {
        arrayOf(rules, collection, kObject);
    }
    arrayOf(rules, "/extensionsUsed", kString);
    arrayOf(rules, "/extensionsRequired", kString);
    rules["/asset"] = kObject;
    rules["/asset/version"] = kString;
    sceneGraph(rules);
    cameras(rules);
    materials(rules);
    textures(rules);
    data(rules);
    return rules;
}

}  // namespace

const JsonRule* gltfJsonRule(const std::string& pattern) {
    static const Rules rules = makeRules();
    const auto found = rules.find(pattern);
    return found == rules.end() ? nullptr : &found->second;
}

}  // namespace patina::gltf
