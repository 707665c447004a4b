#include "state/preferences.h"

#include <algorithm>

namespace patina::editor {

namespace {
constexpr size_t kRecentFiles = 10;
}  // namespace

void rememberRecent(Preferences& preferences, const std::filesystem::path& path) {
    std::error_code error;
    const std::filesystem::path absolute = std::filesystem::absolute(path, error);
    const std::filesystem::path entry = error ? path : absolute.lexically_normal();
    auto& recent = preferences.recentFiles;
    recent.erase(std::remove(recent.begin(), recent.end(), entry), recent.end());
    recent.insert(recent.begin(), entry);
    if (recent.size() > kRecentFiles) {
        recent.resize(kRecentFiles);
    }
}

bool isPreset(const Preferences& preferences, const std::filesystem::path& path) {
    std::error_code error;
    const std::filesystem::path folder = std::filesystem::weakly_canonical(path, error).parent_path();
    const auto& folders = preferences.presetFolders;
    return std::any_of(folders.begin(), folders.end(), [&](const std::filesystem::path& f) {
        std::error_code e;
        return std::filesystem::weakly_canonical(f, e) == folder;
    });
}

}  // namespace patina::editor
