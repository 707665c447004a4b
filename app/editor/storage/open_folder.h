#pragma once
// Shows a folder in the desktop's file manager (the screenshots' folder, after F12).
#include <filesystem>
#include <string>
#include <vector>

#include <sys/types.h>

namespace patina::editor {

// Openers still running after their moment (a file manager kept in the foreground), each
// reaped by a later showFolder so that none stays a zombie for long (Jobs::folderOpeners).
using RunningOpeners = std::vector<pid_t>;

// Runs `opener` (xdg-open, from Debian's xdg-utils) on `folder`, without a shell. Returns ""
// when it started and did not fail within a moment, else what went wrong in words, naming the
// folder so it can be opened by hand. One still running then is kept in `running`.
std::string showFolder(const std::filesystem::path& folder, const std::string& opener, RunningOpeners& running);

}  // namespace patina::editor
