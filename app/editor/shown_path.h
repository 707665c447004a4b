#pragma once
// Paths as the UI shows them: from a place the user knows (their home folder, their presets
// folder) rather than from the root of the machine's file system. Nothing here is written into
// a file: an export or a save keeps its own paths (or none).
#include <filesystem>
#include <string>

namespace patina::editor {

// `path` made whole (lexically normal, absolute from the working folder) and written from the
// nearest place the user knows: inside `near` (the model's folder, say), from it
// ("textures/worn.png"); under the home folder ($HOME), from it ("~/Pictures/shot.png");
// elsewhere the whole path.
std::string shownPath(const std::filesystem::path& path, const std::filesystem::path& near = {});
// Whether `path` is `folder` or inside it (both made whole first).
bool isInside(const std::filesystem::path& path, const std::filesystem::path& folder);

}  // namespace patina::editor
