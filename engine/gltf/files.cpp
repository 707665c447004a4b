#include "gltf/files.h"

#include <algorithm>
#include <cctype>

#include <fcntl.h>

#include "files/input_error.h"
#include "files/regular_file.h"

namespace patina::gltf {

namespace fs = std::filesystem;

namespace {

// `name` starts every message; `budget` is what the model may still read.
std::vector<uint8_t> readRegularFile(const fs::path& path, int flags, const std::string& name,
                                     uint64_t budget) {
    const RegularFile file(path, flags, name);
    file.requireAtMost(kMaxFileBytes, "files");
    if (file.size() > budget) {
        throw InputError(name + ": with the files read before it, the model passes the limit of " +
                         mebibytes(kMaxTotalBytes) + " for all its files");
    }
    return file.readAll();
}

// RFC 3986: a scheme is a letter, then letters, digits, '+', '-' or '.', then ':'.
bool hasScheme(const std::string& uri) {
    const size_t colon = uri.find(':');
    if (colon == std::string::npos || colon == 0 || !std::isalpha(static_cast<unsigned char>(uri[0]))) {
        return false;
    }
    return std::all_of(uri.begin(), uri.begin() + long(colon), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '+' || c == '-' || c == '.';
    });
}

// Component by component, so that /a/bc is not taken to be inside /a/b.
bool isInside(const fs::path& path, const fs::path& folder) {
    auto p = path.begin();
    for (auto f = folder.begin(); f != folder.end(); ++f, ++p) {
        if (f->empty() && std::next(f) == folder.end()) {
            break;   // a trailing separator
        }
        if (p == path.end() || *p != *f) {
            return false;
        }
    }
    return true;
}

}  // namespace

std::vector<uint8_t> readModelFile(const fs::path& path) {
    return readRegularFile(path, 0, path.string(), kMaxFileBytes);
}

ModelFolder::ModelFolder(const fs::path& modelPath, std::string source)
    : source_(std::move(source)) {
    std::error_code error;
    folder_ = fs::canonical(fs::absolute(modelPath, error).parent_path(), error);
    if (error) {
        throw InputError(source_ + ": cannot resolve the model's folder: " + error.message());
    }
    baseDir_ = folder_.string();
}

tinygltf::FsCallbacks ModelFolder::callbacks() {
    return {&ModelFolder::fileExists, [](const std::string& path, void*) { return path; },
            &ModelFolder::readWholeFile, &ModelFolder::refuseWrite, this};
}

std::string ModelFolder::uriOf(const std::string& path) const {
    const std::string prefix = baseDir_.back() == '/' ? baseDir_ : baseDir_ + "/";
    return path.compare(0, prefix.size(), prefix) == 0 ? path.substr(prefix.size()) : std::string();
}

void ModelFolder::refuse(const std::string& uri, const std::string& why) const {
    std::string shown;   // control characters would cut or garble the message
    for (const char c : uri) {
        shown += static_cast<unsigned char>(c) < 0x20 || c == 0x7f ? '?' : c;
    }
    throw InputError(source_ + ": '" + shown + "' " + why);
}

fs::path ModelFolder::resolve(const std::string& uri) const {
    if (uri.find('\0') != std::string::npos) {
        refuse(uri, "contains a NUL character");
    }
    if (hasScheme(uri)) {
        refuse(uri, "is a remote or non-file URI; only paths relative to the model's folder and "
                    "base64 data: URIs are allowed");
    }
    const fs::path relative(uri);
    if (relative.is_absolute()) {
        refuse(uri, "is an absolute path; only paths relative to the model's folder are allowed");
    }
    const fs::path normal = relative.lexically_normal();
    if (!normal.empty() && *normal.begin() == "..") {
        refuse(uri, "leads outside the model's folder");
    }
    std::error_code error;
    const fs::path target = fs::canonical(folder_ / normal, error);
    if (error) {
        return {};   // missing: tinygltf reports "File not found"
    }
    if (!isInside(target, folder_)) {
        refuse(uri, "leads outside the model's folder through a symbolic link");
    }
    if (!fs::is_regular_file(target, error)) {
        refuse(uri, "is not a regular file");
    }
    return target;
}

bool ModelFolder::fileExists(const std::string& path, void* self) {
    const auto* folder = static_cast<const ModelFolder*>(self);
    const std::string uri = folder->uriOf(path);
    return !uri.empty() && !folder->resolve(uri).empty();
}

bool ModelFolder::readWholeFile(std::vector<unsigned char>* out, std::string* error,
                                const std::string& path, void* self) {
    auto* folder = static_cast<ModelFolder*>(self);
    const std::string uri = folder->uriOf(path);
    const fs::path target = uri.empty() ? fs::path() : folder->resolve(uri);
    if (target.empty()) {
        *error = "not found inside the model's folder";
        return false;
    }
    // O_NOFOLLOW: the last component was no link when resolved, and must not become one.
    *out = readRegularFile(target, O_NOFOLLOW, folder->source_ + ": '" + uri + "'",
                           kMaxTotalBytes - folder->bytesRead_);
    folder->bytesRead_ += out->size();
    return true;
}

bool ModelFolder::refuseWrite(std::string* error, const std::string&,
                              const std::vector<unsigned char>&, void*) {
    *error = "loading a model never writes files";
    return false;
}

}  // namespace patina::gltf
