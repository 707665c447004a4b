#include "shown_path.h"

#include <cstdlib>
#include <optional>

namespace patina::editor {

namespace {
std::filesystem::path whole(const std::filesystem::path& path) {
    std::error_code error;
    const std::filesystem::path absolute = std::filesystem::absolute(path, error);
    const std::filesystem::path normal = (error ? path : absolute).lexically_normal();
    return normal.has_filename() || !normal.has_relative_path() ? normal : normal.parent_path();   // "/x/" is "/x"
}

// The part of `path` after `folder`, or nothing when `path` is not inside it.
std::optional<std::filesystem::path> under(const std::filesystem::path& path, const std::filesystem::path& folder) {
    const std::filesystem::path rest = whole(path).lexically_relative(whole(folder));
    if (rest.empty() || *rest.begin() == "..") {
        return std::nullopt;
    }
    return rest;
}
}  // namespace

bool isInside(const std::filesystem::path& path, const std::filesystem::path& folder) {
    return !folder.empty() && under(path, folder).has_value();
}

std::string shownPath(const std::filesystem::path& path, const std::filesystem::path& near) {
    if (!near.empty()) {
        if (const auto rest = under(path, near); rest && *rest != ".") {
            return rest->string();
        }
    }
    const char* home = std::getenv("HOME");
    if (home && *home && std::filesystem::path(home) != "/") {
        if (const auto rest = under(path, home)) {
            return *rest == "." ? "~" : "~/" + rest->string();
        }
    }
    return whole(path).string();
}

}  // namespace patina::editor
