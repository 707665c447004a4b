#pragma once
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "image/image.h"
#include "scene/scene.h"

namespace patina {

// The keyword under which the editor stores sceneToJson(scene) in its PNGs.
inline constexpr const char* kSceneTextKeyword = "patina-scene";

// encodePng(image) with one uncompressed iTXt chunk per entry, right after IHDR. Keywords are
// Latin-1 bytes (1 to 79, printable, no leading, trailing or double spaces); text is UTF-8.
// Throws std::invalid_argument for a bad keyword or text that is not UTF-8.
std::vector<uint8_t> encodePngWithText(const LdrImage& image,
                                       const std::vector<std::pair<std::string, std::string>>& text);

// The tEXt and uncompressed iTXt entries of a PNG, keyword -> UTF-8 text (tEXt's Latin-1 is
// converted); the first entry wins for a repeated keyword. Compressed entries are skipped.
// Throws InputError for anything that is not a well-formed PNG chunk stream up to IEND.
std::map<std::string, std::string> readPngText(const std::vector<uint8_t>& bytes);

// The scene stored under kSceneTextKeyword in a PNG; nullopt when there is none. Throws
// InputError naming `source` when it is not a PNG or the scene is not valid.
std::optional<Scene> sceneFromPngBytes(const std::vector<uint8_t>& bytes, const std::string& source,
                                       std::vector<std::string>& warnings);

// Screenshots are far smaller; a larger file is refused before it is read.
constexpr uint64_t kMaxPngBytes = uint64_t(512) << 20;

// sceneFromPngBytes of a regular file of at most kMaxPngBytes, named by its path.
std::optional<Scene> sceneFromPng(const std::filesystem::path& path,
                                  std::vector<std::string>& warnings);
// The same for a PNG opened as a scene: InputError when it holds none.
Scene screenshotScene(const std::filesystem::path& path, std::vector<std::string>& warnings);

}  // namespace patina
