#pragma once
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "environment/environment.h"

namespace patina {

// An environment light's `source` ("builtin:NAME" or an .hdr or .exr file's path) read but not
// yet made ready: its key (the file's contents, or a built-in's name, with the settings)
// decides whether it must be. Throws InputError naming the file for one that cannot be read,
// or an unknown built-in.
struct EnvironmentSource {
    std::string source;
    std::vector<uint8_t> bytes;   // a file's; empty for a built-in
    uint64_t key = 0;
};
EnvironmentSource readEnvironmentSource(const std::string& source, const EnvironmentSettings& settings);

// `read` made ready to light with: decoded, and its prefiltered chain and coefficients read
// from the disk cache (environmentCacheFolder, by key) or made and kept there, so a second start
// only decodes (a chain made is prefiltered by `prefilter`). Keeps nothing in memory:
// assets/AssetCache shares what is made. Throws InputError for a file that cannot be decoded;
// null when `progress` stopped it.
std::shared_ptr<const Environment> makeEnvironment(const EnvironmentSource& read, const EnvironmentSettings& settings,
                                                   const Progress& progress = {},
                                                   PrefilterFunction prefilter = prefilterCube);

// $PATINA_CACHE_DIR, else $XDG_CACHE_HOME/patina, else ~/.cache/patina; empty when none of
// these can be named (then nothing is kept on disk).
std::filesystem::path environmentCacheFolder();

}  // namespace patina
