#include "gltf/images.h"

#include <algorithm>
#include <atomic>
#include <climits>
#include <cstring>
#include <memory>
#include <mutex>
#include <span>

#include <stb_image.h>
#include <webp/decode.h>

#include "common/parallel_for.h"
#include "files/input_error.h"
#include "gltf/accessor.h"
#include "gltf/files.h"

namespace patina::gltf {

namespace {

// Section 3.8.3: images are PNG or JPEG, and EXT_texture_webp's WebP; told apart by their
// signatures, not by mimeType or the file's extension. Nothing else reaches stb_image, which
// would read BMP, GIF, PSD and more.
bool isPngOrJpeg(std::span<const uint8_t> bytes) {
    static constexpr uint8_t kPng[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    static constexpr uint8_t kJpeg[3] = {0xFF, 0xD8, 0xFF};
    return (bytes.size() >= sizeof kPng && std::memcmp(bytes.data(), kPng, sizeof kPng) == 0) ||
           (bytes.size() >= sizeof kJpeg && std::memcmp(bytes.data(), kJpeg, sizeof kJpeg) == 0);
}

// RIFF's header, its size, then "WEBP" (the WebP container specification, "RIFF Header").
bool isWebp(std::span<const uint8_t> bytes) {
    return bytes.size() >= 12 && std::memcmp(bytes.data(), "RIFF", 4) == 0 &&
           std::memcmp(bytes.data() + 8, "WEBP", 4) == 0;
}

// The image's size from its header through the decoder its signature names: false when it
// cannot be read.
bool imageSize(std::span<const uint8_t> bytes, int& width, int& height) {
    if (isWebp(bytes)) {
        return WebPGetInfo(bytes.data(), bytes.size(), &width, &height) != 0;
    }
    int channels = 0;
    return stbi_info_from_memory(bytes.data(), int(bytes.size()), &width, &height, &channels) != 0;
}

std::string imageName(const tinygltf::Image& image, size_t index) {
    return !image.uri.empty() ? image.uri : !image.name.empty() ? image.name : "image " + std::to_string(index);
}

// An image's size from its header, against the limits: why it cannot be had, or "". Run in
// the images' order, so that the budget of decoded bytes goes to the first ones.
class ImageBudget {
public:
    std::string admit(std::span<const uint8_t> bytes, uint64_t& size) {
        if (!isPngOrJpeg(bytes) && !isWebp(bytes)) {
            return "is neither PNG, JPEG nor WebP";
        }
        if (bytes.size() > size_t(INT_MAX)) {   // stb_image takes an int
            return "is over 2 GiB";
        }
        int width = 0, height = 0;
        if (!imageSize(bytes, width, height)) {
            return std::string("cannot be read: ") +
                   (isWebp(bytes) ? "not a WebP image libwebp reads" : decoderReason(stbi_failure_reason()));
        }
        if (width > kGltfMaxImageSide || height > kGltfMaxImageSide) {
            return "is " + std::to_string(width) + " x " + std::to_string(height) + " pixels, over Patina's limit of " +
                   std::to_string(kGltfMaxImageSide) + " a side";
        }
        size = uint64_t(width) * uint64_t(height) * 4;
        if (size > kGltfMaxImageBytes - decoded_) {
            return "would take the model's decoded images past Patina's limit of " +
                   std::to_string(kGltfMaxImageBytes >> 20) + " MiB";
        }
        decoded_ += size;
        return "";
    }

private:
    uint64_t decoded_ = 0;
};

// A WebP image (lossy or lossless, with or without alpha) as RGBA, through libwebp.
std::string decodeWebp(std::span<const uint8_t> bytes, uint64_t size, ModelImage& out) {
    const std::unique_ptr<uint8_t, void (*)(void*)> pixels(
        WebPDecodeRGBA(bytes.data(), bytes.size(), &out.width, &out.height), WebPFree);
    if (!pixels) {
        return "cannot be decoded: libwebp refuses it";
    }
    if (uint64_t(out.width) * uint64_t(out.height) * 4 != size) {
        return "decodes to another size than its header gives";
    }
    out.rgba.assign(pixels.get(), pixels.get() + size);
    return "";
}

// Decodes an admitted image of `size` bytes decoded into `out`: why it failed, or "". Safe on
// several threads at once (stb_image keeps its failure reason per thread).
std::string decode(std::span<const uint8_t> bytes, uint64_t size, ModelImage& out) {
    if (isWebp(bytes)) {
        return decodeWebp(bytes, size, out);
    }
    int channels = 0;
    // Four channels asked for: grey, grey-alpha, RGB and palettes all become RGBA, 16 bits 8.
    const std::unique_ptr<stbi_uc, void (*)(void*)> pixels(
        stbi_load_from_memory(bytes.data(), int(bytes.size()), &out.width, &out.height, &channels, 4),
        stbi_image_free);
    if (!pixels) {
        return std::string("cannot be decoded: ") + decoderReason(stbi_failure_reason());
    }
    if (uint64_t(out.width) * uint64_t(out.height) * 4 != size) {
        return "decodes to another size than its header gives";
    }
    out.rgba.assign(pixels.get(), pixels.get() + size);
    return "";
}

}  // namespace

std::optional<std::vector<int>> decodeImages(const tinygltf::Model& document, const std::vector<bool>& used,
                                             Model& model, const std::string& source, const Progress& progress) {
    struct Pending {
        size_t index;
        std::span<const uint8_t> bytes;
        uint64_t size = 0;
        ModelImage image;
        std::string problem;
    };
    std::vector<Pending> pending;
    ImageBudget budget;
    for (size_t i = 0; i < document.images.size(); ++i) {
        if (!used[i]) {
            continue;
        }
        const tinygltf::Image& image = document.images[i];
        // loadDocument kept a file's or data: URI's bytes; a view's are checked here.
        Pending next;
        next.index = i;
        next.bytes = image.bufferView != -1 ? bufferViewBytes(document, image.bufferView,
                                                              source + ": /images/" + std::to_string(i), source)
                                            : std::span<const uint8_t>(image.image);
        next.image.name = imageName(image, i);
        next.problem = image.bufferView == -1 && !image.as_is ? "is not found in the model's folder"
                                                               : budget.admit(next.bytes, next.size);
        pending.push_back(std::move(next));
    }
    // The decoding, a model's slowest step, on every core: an image a thread. Asked after each
    // image whether to go on: a cancelled model with 4K maps stops within an image a core.
    const bool decoding = std::any_of(pending.begin(), pending.end(), [](const Pending& p) { return p.problem.empty(); });
    std::atomic<bool> stopped = progress && !progress(0.0f);
    std::mutex telling;
    size_t done = 0;
    parallelFor(decoding && !stopped ? pending.size() : 0, [&](size_t k) {
        if (stopped) {
            return;
        }
        if (pending[k].problem.empty()) {
            pending[k].problem = decode(pending[k].bytes, pending[k].size, pending[k].image);
        }
        if (progress) {
            std::lock_guard lock(telling);
            stopped = stopped || !progress(float(++done) / float(pending.size()));
        }
    });
    if (stopped) {
        return std::nullopt;
    }
    std::vector<int> indices(document.images.size(), -1);
    for (Pending& image : pending) {
        if (!image.problem.empty()) {
            model.notes.push_back("/images/" + std::to_string(image.index) + " (" + image.image.name +
                                  "): " + image.problem + "; the maps that use it are left out");
            continue;
        }
        indices[image.index] = int(model.images.size());
        model.images.push_back(std::move(image.image));
    }
    return indices;
}

ModelImage readImageFile(const std::filesystem::path& path) {
    return readImageFile(path, readModelFile(path));
}

ModelImage readImageFile(const std::filesystem::path& path, const std::vector<uint8_t>& bytes) {
    ModelImage image;
    image.name = path.filename().string();
    uint64_t size = 0;
    std::string problem = ImageBudget().admit(bytes, size);
    if (problem.empty()) {
        problem = decode(bytes, size, image);
    }
    if (!problem.empty()) {
        throw InputError(path.string() + ": the image " + problem);
    }
    return image;
}

}  // namespace patina::gltf
