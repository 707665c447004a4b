#pragma once
// A folder of its own for one fuzzer process (fuzzers may run side by side), removed when the
// process exits normally; after a crash it is left for the artifact's sake.
#include <cstdlib>
#include <filesystem>
#include <string>

namespace patina::fuzz {

inline const std::filesystem::path& scratchFolder() {
    struct Folder {
        std::filesystem::path path;
        Folder() {
            std::string name = (std::filesystem::temp_directory_path() / "patina-fuzz-XXXXXX").string();
            if (!::mkdtemp(name.data())) {
                std::abort();
            }
            path = name;
        }
        ~Folder() {
            std::error_code ignored;
            std::filesystem::remove_all(path, ignored);
        }
    };
    static const Folder folder;
    return folder.path;
}

}  // namespace patina::fuzz
