#pragma once
// File access for one glTF model: the model file itself, and through tinygltf's file callbacks
// only regular files inside the model's folder (docs/FORMATS.md, "glTF": confinement).
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <tiny_gltf.h>

namespace patina::gltf {

constexpr uint64_t kMaxFileBytes = uint64_t(512) << 20;    // the model and each file it names
constexpr uint64_t kMaxTotalBytes = uint64_t(1) << 30;     // everything read for one model

// The model file, at most kMaxFileBytes; InputError naming it otherwise.
std::vector<uint8_t> readModelFile(const std::filesystem::path& path);

// The folder of one model. Its callbacks resolve each URI tinygltf asks for against the
// folder and throw InputError("SOURCE: 'URI': ...") for a remote URI, an absolute path, a
// path leading outside the folder (by `..` or a symbolic link), a file that is not regular or
// too large, or when the model's files together pass kMaxTotalBytes.
class ModelFolder {
public:
    ModelFolder(const std::filesystem::path& modelPath, std::string source);
    ModelFolder(const ModelFolder&) = delete;
    ModelFolder& operator=(const ModelFolder&) = delete;

    // What tinygltf gets as its base_dir: the folder, canonical.
    const std::string& baseDir() const { return baseDir_; }
    // Callbacks bound to this object, which must outlive the load.
    tinygltf::FsCallbacks callbacks();

private:
    static bool fileExists(const std::string& path, void* self);
    static bool readWholeFile(std::vector<unsigned char>* out, std::string* error,
                              const std::string& path, void* self);
    static bool refuseWrite(std::string* error, const std::string& path,
                            const std::vector<unsigned char>& bytes, void* self);

    // The URI inside a path tinygltf built as JoinPath(baseDir, uri); empty for its other
    // attempt, relative to the working directory, which is never allowed.
    std::string uriOf(const std::string& path) const;
    // The file the URI names, checked; throws InputError for a URI that breaks a rule.
    std::filesystem::path resolve(const std::string& uri) const;
    [[noreturn]] void refuse(const std::string& uri, const std::string& why) const;

    std::filesystem::path folder_;
    std::string baseDir_;
    std::string source_;
    uint64_t bytesRead_ = 0;
};

}  // namespace patina::gltf
