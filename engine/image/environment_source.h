#pragma once
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "environment/environment.h"
#include "scene/scene.h"

namespace patina {

// The environment of a light's `source` ("builtin:NAME" or an .hdr or .exr file's path) made
// ready to light with. Made once per source, contents and settings: a process-wide cache
// shares what is still in use, and the prefiltered chain and coefficients are kept on disk
// (environmentCacheFolder) keyed by the file's contents and the settings, so a second start
// only decodes. Throws InputError naming the file for one that cannot be read or decoded; a
// note about replaced pixels goes to `warnings`. Null when `progress` stopped it.
std::shared_ptr<const Environment> loadEnvironment(const std::string& source, std::vector<std::string>& warnings,
                                                   const EnvironmentSettings& settings = {},
                                                   const Progress& progress = {});

// Sets scene.resolvedEnvironment from its enabled environment light's source, a built-in too
// (through the disk cache), or null without one.
// Throws as loadEnvironment, leaving the scene as it was.
void resolveEnvironment(Scene& scene, std::vector<std::string>& warnings);

// $PATINA_CACHE_DIR, else $XDG_CACHE_HOME/patina, else ~/.cache/patina; empty when none of
// these can be named (then nothing is kept on disk).
std::filesystem::path environmentCacheFolder();

}  // namespace patina
