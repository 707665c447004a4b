#pragma once
// Shows a folder in the desktop's file manager (the screenshots' folder, after F12).
#include <filesystem>
#include <string>

namespace patina::editor {

// Runs `opener` (xdg-open, from Debian's xdg-utils) on `folder`, without a shell. Returns ""
// when it started and did not fail within a moment, else what went wrong in words, naming the
// folder so it can be opened by hand.
std::string showFolder(const std::filesystem::path& folder, const std::string& opener = "xdg-open");

}  // namespace patina::editor
