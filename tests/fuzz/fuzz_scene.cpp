// Scene JSON through the loader scene files go through. A "material" path is resolved in an
// empty folder (an absolute one is read, as a user's file may name one). Refusals are
// InputErrors; anything else is a bug. What loads must write back and load the same.
#include <cstdint>
#include <cstdlib>

#include "io/json_writer.h"
#include "io/scene_file.h"
#include "scratch_folder.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace patina;
    std::vector<std::string> warnings;
    Scene scene;
    try {
        const std::string text(reinterpret_cast<const char*>(data), size);
        scene = sceneFromJson(parseJsonText(text, "fuzz.json"), "fuzz.json", fuzz::scratchFolder(), warnings);
    } catch (const InputError&) {
        return 0;
    }
    const Json written = parseJsonText(prettyJson(sceneToJson(scene)), "written.json");
    if (!(sceneFromJson(written, "written.json", fuzz::scratchFolder(), warnings) == scene)) {
        std::abort();
    }
    return 0;
}
