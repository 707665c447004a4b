#include "gltf/document.h"

#include <algorithm>
#include <new>

#include "common/one_line.h"
#include "gltf/draco.h"
#include "gltf/extensions.h"
#include "gltf/files.h"
#include "gltf/glb.h"
#include "gltf/meshopt.h"
#include "gltf/json_check.h"
#include "io/json_reader.h"
#include "files/input_error.h"

namespace patina::gltf {

namespace {

// tinygltf's image callback: the encoded bytes are kept for images.cpp, which decodes only
// what a material uses. A buffer view's bytes are left where they are: images.cpp reads them
// after checking the view against its buffer, which tinygltf does not.
bool keepImageBytes(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                    const unsigned char* bytes, int size, void*) {
    if (image->bufferView == -1) {
        image->image.assign(bytes, bytes + size);
        image->as_is = true;
    }
    return true;
}

// The JSON tinygltf is given: nothing where it is the file's, else the file's rewritten where
// an extension needs it (Draco's indices moved, meshopt's fallback buffers stood in for).
std::optional<std::string> jsonForTinygltf(std::string_view json, const std::string& source) {
    if (json.find(kDraco) == std::string_view::npos && json.find(kMeshopt) == std::string_view::npos) {
        return std::nullopt;
    }
    Json document = parseJsonText(std::string(json), source);
    const bool moved = moveDracoIndicesIntoTheExtension(document);
    const bool stoodIn = standInForMeshoptFallbacks(document);
    return moved || stoodIn ? std::optional(document.dump()) : std::nullopt;
}

bool parse(tinygltf::TinyGLTF& loader, tinygltf::Model& model, const std::vector<uint8_t>& bytes,
           const std::string& baseDir, std::string& error, std::string& warning, const std::string& source) {
    if (looksLikeGlb(bytes)) {
        const GlbChunks glb = splitGlb(bytes, source);
        refuseUndrawnRequired(checkGltfJson(glb.json, true, source), source);
        const std::optional<std::string> rewritten = jsonForTinygltf(glb.json, source);
        // tinygltf reads the layout again from the header: give it one without other chunks.
        const bool asIs = glb.onlyJsonAndBin && !rewritten;
        const std::vector<uint8_t> joined =
            asIs ? std::vector<uint8_t>()
                 : joinGlb(rewritten ? std::string_view(*rewritten) : glb.json, glb.bin, glb.binSize);
        const std::vector<uint8_t>& clean = asIs ? bytes : joined;
        return loader.LoadBinaryFromMemory(&model, &error, &warning, clean.data(), unsigned(clean.size()), baseDir);
    }
    const std::string_view json(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    if (!opensLikeJson(json, "{")) {
        throw InputError(source + ": neither a glTF binary (a .glb starts with \"glTF\") nor glTF JSON (a .gltf is "
                                  "a JSON object)");
    }
    refuseUndrawnRequired(checkGltfJson(json, false, source), source);
    const std::optional<std::string> rewritten = jsonForTinygltf(json, source);
    const std::string_view text = rewritten ? std::string_view(*rewritten) : json;
    return loader.LoadASCIIFromString(&model, &error, &warning, text.data(), unsigned(text.size()), baseDir);
}

// tinygltf says a missing buffer file as "File not found : NAME" (images never get here: a
// missing one is a warning of images.cpp's); said as Patina says the images'.
std::string saidPlainly(std::string message) {
    const std::string tinygltfs = "File not found : ";
    for (size_t at = message.find(tinygltfs); at != std::string::npos; at = message.find(tinygltfs, at)) {
        const size_t end = std::min(message.find(';', at), message.size());
        const std::string name = message.substr(at + tinygltfs.size(), end - at - tinygltfs.size());
        const std::string said = "the buffer file '" + name + "' is not found in the model's folder";
        message.replace(at, end - at, said);
        at += said.size();
    }
    return message;
}

}  // namespace

tinygltf::Model loadDocument(const std::filesystem::path& path, const std::vector<uint8_t>& bytes,
                             const std::string& source) {
    ModelFolder folder(path, source);
    tinygltf::TinyGLTF loader;
    loader.SetFsCallbacks(folder.callbacks());
    loader.SetImageLoader(&keepImageBytes, nullptr);
    tinygltf::Model model;
    std::string error, warning;
    bool loaded = false;
    try {
        loaded = parse(loader, model, bytes, folder.baseDir(), error, warning, source);
    } catch (const InputError&) {
        throw;
    } catch (const std::bad_alloc&) {
        throw InputError(source + ": out of memory while loading");
    } catch (const std::exception& exception) {
        throw InputError(source + ": " + exception.what());
    }
    // tinygltf also reports some errors (an array of the wrong length) without failing, and
    // fails on some (an empty image file) with only a warning.
    if (!loaded || !error.empty()) {
        // tinygltf collects messages line by line: one line, its lines apart by ';'.
        const std::string message = saidPlainly(oneLine(error.empty() ? warning : error, ';'));
        throw InputError(source + ": " + (message.empty() ? "cannot be loaded" : message));
    }
    // A stream of a few bytes may declare up to kMaxMeshoptBytes: running out is bad input too.
    try {
        decodeMeshoptViews(model, source);
    } catch (const std::bad_alloc&) {
        throw InputError(source + ": out of memory while decoding its meshopt-compressed views");
    }
    return model;
}

}  // namespace patina::gltf
