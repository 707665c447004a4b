#include "environment/environment_source.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>

#include "common/content_hash.h"
#include "environment/builtin_environments.h"
#include "environment/equirect.h"
#include "environment/environment_files.h"
#include "files/file_bytes.h"
#include "files/input_error.h"
#include "files/regular_file.h"

namespace patina {

namespace {
// Bumped whenever the prefilter, the irradiance or the built-ins change what they make.
// 2: the lod mapping starts at the roughness floor; 3: the irradiance map instead of 9 SH coefficients.
constexpr uint32_t kCacheVersion = 3;
constexpr uint64_t kMaxEnvironmentFileBytes = uint64_t(512) << 20;

uint64_t settingsHash(const EnvironmentSettings& settings, uint64_t hash) {
    const int32_t values[] = {int32_t(kCacheVersion), settings.prefilter.levels, int32_t(settings.prefilter.samples),
                              kIrradianceFaceSize, kIrradianceCellSize};
    return hashBytes(values, sizeof values, hash);
}

size_t levelBytes(const CubeLevel& level) {
    return 4 + 6 * level.faces[0].size() * sizeof(float);
}

// The cache file: "PATINAENV", version, level count, each level's size and texels, then the
// irradiance map as one more level. Floats as the machine stores them (a cache, not an
// interchange format).
std::vector<uint8_t> serialise(const Environment& environment) {
    size_t total = 9 + 4 + 4 + levelBytes(environment.irradiance);
    for (const CubeLevel& level : environment.prefiltered) {
        total += levelBytes(level);
    }
    std::vector<uint8_t> bytes(total);
    size_t at = 0;
    auto put = [&](const void* data, size_t size) {
        std::memcpy(bytes.data() + at, data, size);
        at += size;
    };
    put("PATINAENV", 9);
    put(&kCacheVersion, 4);
    const uint32_t levels = uint32_t(environment.prefiltered.size());
    put(&levels, 4);
    auto putLevel = [&](const CubeLevel& level) {
        const int32_t size = level.size;
        put(&size, 4);
        for (const std::vector<float>& face : level.faces) {
            put(face.data(), face.size() * sizeof(float));
        }
    };
    for (const CubeLevel& level : environment.prefiltered) {
        putLevel(level);
    }
    putLevel(environment.irradiance);
    return bytes;
}

// False for a file that is not a complete cache entry of this version (then it is remade).
bool deserialise(const std::vector<uint8_t>& bytes, Environment& environment) {
    size_t at = 0;
    auto get = [&](void* data, size_t size) {
        if (bytes.size() - at < size) {
            return false;
        }
        std::memcpy(data, bytes.data() + at, size);
        at += size;
        return true;
    };
    char magic[9];
    uint32_t version = 0, levels = 0;
    if (!get(magic, 9) || std::memcmp(magic, "PATINAENV", 9) != 0 || !get(&version, 4) || version != kCacheVersion ||
        !get(&levels, 4) || levels == 0 || levels > 16) {
        return false;
    }
    auto getLevel = [&](CubeLevel& level) {
        int32_t size = 0;
        if (!get(&size, 4) || size < 1 || size > 4096) {
            return false;
        }
        level = CubeLevel(size);
        for (std::vector<float>& face : level.faces) {
            if (!get(face.data(), face.size() * sizeof(float))) {
                return false;
            }
        }
        return true;
    };
    CubeChain chain(levels);
    for (CubeLevel& level : chain) {
        if (!getLevel(level)) {
            return false;
        }
    }
    CubeLevel irradiance;
    if (!getLevel(irradiance) || irradiance.size != kIrradianceFaceSize || at != bytes.size()) {
        return false;
    }
    environment.prefiltered = std::move(chain);
    environment.irradiance = std::move(irradiance);
    return true;
}

HdrImage decodeSource(const EnvironmentSource& read) {
    if (const auto name = builtinName(read.source)) {
        return *builtinEnvironment(*name);
    }
    return decodeEnvironmentImage(read.bytes, read.source);
}

std::shared_ptr<const Environment> fromDiskCache(HdrImage& image, uint64_t key, const std::string& source,
                                                 const EnvironmentSettings& settings) {
    const std::filesystem::path folder = environmentCacheFolder();
    if (folder.empty()) {
        return nullptr;
    }
    char name[32];
    std::snprintf(name, sizeof name, "%016llx.env", static_cast<unsigned long long>(key));
    std::error_code error;
    if (!std::filesystem::is_regular_file(folder / name, error)) {
        return nullptr;
    }
    auto environment = std::make_shared<Environment>();
    try {
        if (!deserialise(readFileBytes(folder / name), *environment)) {
            return nullptr;
        }
    } catch (const std::exception&) {
        return nullptr;   // unreadable: made again, and written over
    }
    environment->source = source;
    environment->settings = settings;
    environment->replacedPixels = replaceInvalidPixels(image);
    environment->image = std::move(image);
    return environment;
}

void toDiskCache(const Environment& environment, uint64_t key) {
    const std::filesystem::path folder = environmentCacheFolder();
    if (folder.empty()) {
        return;
    }
    char name[32];
    std::snprintf(name, sizeof name, "%016llx.env", static_cast<unsigned long long>(key));
    try {
        std::filesystem::create_directories(folder);
        writeFileAtomic(folder / name, serialise(environment));
    } catch (const std::exception&) {
        // A cache that cannot be written costs the next start the prefilter, nothing else.
    }
}
}  // namespace

std::filesystem::path environmentCacheFolder() {
    if (const char* dir = std::getenv("PATINA_CACHE_DIR"); dir && *dir) {
        return dir;
    }
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) {
        return std::filesystem::path(xdg) / "patina";
    }
    if (const char* home = std::getenv("HOME"); home && *home) {
        return std::filesystem::path(home) / ".cache" / "patina";
    }
    return {};
}

EnvironmentSource readEnvironmentSource(const std::string& source, const EnvironmentSettings& settings) {
    if (const auto name = builtinName(source)) {
        // Known by name: the image is generated once, by makeEnvironment, and only on a miss.
        const auto names = builtinEnvironmentNames();
        if (std::find(names.begin(), names.end(), *name) == names.end()) {
            throw InputError(source + ": no such built-in environment");
        }
        return {source, {}, settingsHash(settings, hashBytes(source.data(), source.size()))};
    }
    RegularFile file(source, 0, source);
    file.requireAtMost(kMaxEnvironmentFileBytes, "environment images");
    EnvironmentSource read{source, file.readAll(), 0};
    read.key = settingsHash(settings, hashBytes(read.bytes.data(), read.bytes.size()));
    return read;
}

std::shared_ptr<const Environment> makeEnvironment(const EnvironmentSource& read, const EnvironmentSettings& settings,
                                                   const Progress& progress, PrefilterFunction prefilter) {
    // Built-ins go through the disk cache too: generating the studio takes milliseconds, its
    // prefilter a third of a second, reading it back a few milliseconds.
    HdrImage image = decodeSource(read);
    std::shared_ptr<const Environment> environment = fromDiskCache(image, read.key, read.source, settings);
    if (!environment) {
        environment = prepareEnvironment(std::move(image), read.source, settings, progress, prefilter);
        if (environment) {
            toDiskCache(*environment, read.key);
        }
    }
    return environment;
}

}  // namespace patina
