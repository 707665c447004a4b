#include "gltf/import.h"

#include <cctype>
#include <new>

#include "common/one_line.h"
#include "gltf/files.h"
#include "gltf/geometry.h"
#include "gltf/glb.h"
#include "gltf/json_check.h"
#include "gltf/material.h"
#include "io/input_error.h"

namespace patina {

namespace {

// Extensions a file may require: Patina reads these, or ignores only textures they change.
bool canRequire(const std::string& extension) {
    return extension == "KHR_materials_specular" || extension == "KHR_materials_ior" ||
           extension == "KHR_texture_transform";
}

// Images are never drawn: they are read (inside the folder, within the limits) but not decoded.
bool skipImage(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int,
               void*) {
    return true;
}

tinygltf::Model loadModel(const std::filesystem::path& path, const std::string& source) {
    const std::vector<uint8_t> bytes = gltf::readModelFile(path);
    gltf::ModelFolder folder(path, source);
    tinygltf::TinyGLTF loader;
    loader.SetFsCallbacks(folder.callbacks());
    loader.SetImageLoader(&skipImage, nullptr);
    tinygltf::Model model;
    std::string error, warning;
    bool loaded = false;
    try {
        if (gltf::looksLikeGlb(bytes)) {
            const gltf::GlbChunks glb = gltf::splitGlb(bytes, source);
            gltf::checkGltfJson(glb.json, true, source);
            // tinygltf reads the layout again from the header: give it one without other chunks.
            const std::vector<uint8_t> joined =
                glb.onlyJsonAndBin ? std::vector<uint8_t>() : gltf::joinGlb(glb.json, glb.bin, glb.binSize);
            const std::vector<uint8_t>& clean = glb.onlyJsonAndBin ? bytes : joined;
            loaded = loader.LoadBinaryFromMemory(&model, &error, &warning, clean.data(), unsigned(clean.size()),
                                                 folder.baseDir());
        } else {
            const std::string_view json(reinterpret_cast<const char*>(bytes.data()), bytes.size());
            gltf::checkGltfJson(json, false, source);
            loaded = loader.LoadASCIIFromString(&model, &error, &warning, json.data(), unsigned(json.size()),
                                                folder.baseDir());
        }
    } catch (const InputError&) {
        throw;
    } catch (const std::bad_alloc&) {
        throw InputError(source + ": out of memory while loading");
    } catch (const std::exception& exception) {
        throw InputError(source + ": " + exception.what());
    }
    // tinygltf also reports some errors (an array of the wrong length) without failing.
    if (!loaded || !error.empty()) {
        // tinygltf collects messages line by line: one line, its lines apart by ';'.
        const std::string message = oneLine(error, ';');
        throw InputError(source + ": " + (message.empty() ? "cannot be loaded" : message));
    }
    for (const std::string& extension : model.extensionsRequired) {
        if (!canRequire(extension)) {
            throw InputError(source + ": requires the extension " + extension + ", which Patina does not support");
        }
    }
    return model;
}

}  // namespace

GltfImport importGltf(const std::filesystem::path& path) {
    const std::string source = path.string();
    const tinygltf::Model model = loadModel(path, source);
    GltfImport result;
    result.mesh = gltf::meshFromModel(model, source);
    if (!model.materials.empty()) {
        result.material = gltf::materialFromGltf(model.materials[0], "/materials/0", source, path.stem().string());
    }
    result.materialCount = model.materials.size();
    result.textureCount = model.textures.size();
    return result;
}

}  // namespace patina
