#pragma once
// The images a model's materials use, decoded (glTF 2.0 section 3.8.3): PNG and JPEG, from a
// buffer view, a data: URI or a file in the model's folder, to 8-bit RGBA with the top row first.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <tiny_gltf.h>

#include "common/progress.h"
#include "model/model.h"

namespace patina::gltf {

constexpr int kGltfMaxImageSide = 16384;                         // pixels, either way
constexpr uint64_t kGltfMaxImageBytes = uint64_t(512) << 20;     // decoded, all of a model's images

// Decodes each glTF image `used` marks into model.images and returns, per glTF image, its index
// there, or -1. An image that cannot be had (a missing file, bytes that are not PNG or JPEG or
// that do not decode, a side over kGltfMaxImageSide, or past kGltfMaxImageBytes with the images
// before it) is -1 with a note in model.notes: the maps using it are left out, the model loads.
// Throws InputError only for a buffer view that does not fit its buffer. `progress` is told the
// share of the images decoded (from the decoding threads, one at a time); nothing when it stops
// the decoding.
std::optional<std::vector<int>> decodeImages(const tinygltf::Model& document, const std::vector<bool>& used,
                                             Model& model, const std::string& source, const Progress& progress = {});

// An image file a scene puts in place of one of a model's maps (Scene's mapsReplaced): PNG or
// JPEG by its signature, at most kGltfMaxImageSide a side, decoded as a model's images are. Its
// name is the file's name, without its folder: a name travels into exports (an exported glTF's
// image once carried the user's whole path), and the scene keeps the path. Throws InputError
// naming the file and why it cannot be had.
ModelImage readImageFile(const std::filesystem::path& path);
// The same from the file's `bytes`, read already (files.h readModelFile: the asset cache reads a
// file once, to hash it and to decode it).
ModelImage readImageFile(const std::filesystem::path& path, const std::vector<uint8_t>& bytes);

}  // namespace patina::gltf
