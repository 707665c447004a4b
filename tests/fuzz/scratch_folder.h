#pragma once
// A folder of its own for one fuzzer process (fuzzers may run side by side), removed when the
// process exits normally; after a crash it is left for the artifact's sake.
#include <filesystem>

#include "io/temporary_folder.h"

namespace patina::fuzz {

inline const std::filesystem::path& scratchFolder() {
    static const TemporaryFolder folder("patina-fuzz");
    return folder.path();
}

}  // namespace patina::fuzz
