// Material JSON through the loader material files go through (loadMaterialFile's parse and
// read). Refusals are InputErrors; anything else escaping, or a crash, is a bug. What loads
// must also survive being saved and embedded in a scene, as the editor does with it.
#include <cstdint>
#include <cstdlib>

#include "io/json_writer.h"
#include "io/scene_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace patina;
    std::vector<std::string> warnings;
    Material material;
    try {
        const std::string text(reinterpret_cast<const char*>(data), size);
        material = materialFromJson(parseJsonText(text, "fuzz.json"), "", "fuzz.json", true, warnings);
    } catch (const InputError&) {
        return 0;
    }
    // As saveMaterialFile writes it, and inline in a scene (a screenshot's, or a scene file).
    const Json saved = parseJsonText(prettyJson(materialToJson(material)), "saved.json");
    if (!(materialFromJson(saved, "", "saved.json", true, warnings) == material)) {
        std::abort();
    }
    Scene scene = defaultScene();
    scene.material = material;
    const Json embedded = parseJsonText(prettyJson(sceneToJson(scene)), "scene.json");
    if (!(sceneFromJson(embedded, "scene.json", {}, warnings) == scene)) {
        std::abort();
    }
    return 0;
}
