#include "storage/save_errors.h"

#include <cerrno>
#include <system_error>

namespace patina::editor {

std::string couldNot(const std::string& action, const std::filesystem::path& file, const std::exception& error) {
    std::error_code ignored;
    const std::filesystem::path absolute = std::filesystem::absolute(file, ignored).lexically_normal();
    const std::string folder = absolute.parent_path().string();
    std::string why = error.what();   // anything not foreseen, as the system said it
    const auto* system = dynamic_cast<const std::system_error*>(&error);   // an errno kept
    if (system && (system->code().category() == std::generic_category() ||
                   system->code().category() == std::system_category())) {
        switch (system->code().value()) {
        case EACCES:
        case EPERM:
        case EROFS: why = "the folder " + folder + " is read-only"; break;
        case ENOENT:
            // A folder that is there may still make no files (/proc, /sys): not "does not exist".
            why = std::filesystem::is_directory(folder, ignored) ? "the folder " + folder + " does not take new files"
                                                                 : "the folder " + folder + " does not exist";
            break;
        case ENOTDIR: why = "part of " + folder + " is a file, not a folder"; break;
        case EISDIR: why = absolute.string() + " is a folder"; break;
        case ENOSPC:
        case EDQUOT: why = "the disk is full"; break;
        case ENAMETOOLONG: why = "the name is too long"; break;
        default: break;
        }
    }
    return "Could not " + action + " " + file.filename().string() + ": " + why;
}

std::string couldNotSave(const std::filesystem::path& file, const std::exception& error) {
    return couldNot("save", file, error);
}

}  // namespace patina::editor
