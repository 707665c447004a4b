#include "gltf/glb.h"

#include "files/input_error.h"

namespace patina::gltf {

namespace {
constexpr uint32_t kMagic = 0x46546C67;       // "glTF"
constexpr uint32_t kJsonChunk = 0x4E4F534A;   // "JSON"
constexpr uint32_t kBinChunk = 0x004E4942;    // "BIN\0"
constexpr size_t kHeaderBytes = 12;
constexpr size_t kChunkHeaderBytes = 8;

uint32_t readU32(const uint8_t* p) {
    return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24;
}

void appendU32(std::vector<uint8_t>& out, uint32_t value) {
    for (int shift = 0; shift < 32; shift += 8) {
        out.push_back(uint8_t(value >> shift));
    }
}

size_t padded(size_t size) { return (size + 3) & ~size_t(3); }

[[noreturn]] void fail(const std::string& source, const std::string& what) {
    throw InputError(source + ": GLB: " + what);
}
}  // namespace

bool looksLikeGlb(const std::vector<uint8_t>& bytes) {
    return bytes.size() >= 4 && readU32(bytes.data()) == kMagic;
}

GlbChunks splitGlb(const std::vector<uint8_t>& bytes, const std::string& source) {
    if (bytes.size() < kHeaderBytes || !looksLikeGlb(bytes)) {
        fail(source, "truncated header (" + std::to_string(bytes.size()) + " bytes)");
    }
    const uint32_t version = readU32(bytes.data() + 4);
    if (version != 2) {
        // Version 1 is glTF 1.0's binary (KHR_binary_glTF): say which glTF it holds.
        fail(source, "version " + std::to_string(version) + " is not supported (only 2" +
                         (version == 1 ? ": this is a glTF 1.0 binary; convert it to glTF 2.0 first, as "
                                         "gltf-pipeline on npm does)"
                                       : ")"));
    }
    const uint32_t length = readU32(bytes.data() + 8);
    if (length != bytes.size()) {
        fail(source, "the header gives a length of " + std::to_string(length) + " bytes but the file has " +
             std::to_string(bytes.size()) + (length > bytes.size() ? " (truncated)" : ""));
    }
    GlbChunks chunks;
    bool haveJson = false;
    size_t offset = kHeaderBytes;
    for (int index = 0; offset < length; ++index) {
        const std::string chunk = "chunk " + std::to_string(index) + " at byte " + std::to_string(offset);
        if (length - offset < kChunkHeaderBytes) {
            fail(source, chunk + ": truncated chunk header");
        }
        const uint32_t size = readU32(bytes.data() + offset);
        const uint32_t type = readU32(bytes.data() + offset + 4);
        const size_t data = offset + kChunkHeaderBytes;
        if (size > length - data) {
            fail(source, chunk + ": " + std::to_string(size) + " bytes run past the end of the file");
        }
        if (size % 4 != 0) {
            fail(source, chunk + ": its length " + std::to_string(size) + " is not a multiple of 4");
        }
        if (index == 0) {
            if (type != kJsonChunk || size == 0) {
                fail(source, "the first chunk must be a non-empty JSON chunk");
            }
            chunks.json = std::string_view(reinterpret_cast<const char*>(bytes.data() + data), size);
            haveJson = true;
        } else if (type == kBinChunk) {
            if (index != 1) {
                fail(source, chunk + ": a BIN chunk may only come second");
            }
            chunks.bin = bytes.data() + data;
            chunks.binSize = size;
        } else if (type == kJsonChunk) {
            fail(source, chunk + ": a second JSON chunk");
        } else {
            chunks.onlyJsonAndBin = false;   // the spec says to skip chunks of unknown types
        }
        offset = data + size;
    }
    if (!haveJson) {
        fail(source, "no JSON chunk");
    }
    return chunks;
}

std::vector<uint8_t> joinGlb(std::string_view json, const uint8_t* bin, size_t binSize) {
    const size_t jsonChunk = padded(json.size());
    const size_t binChunk = binSize == 0 ? 0 : kChunkHeaderBytes + padded(binSize);
    if (kHeaderBytes + kChunkHeaderBytes + jsonChunk + binChunk > UINT32_MAX) {
        throw InputError("the model is too large for a GLB file (4 GiB)");
    }
    std::vector<uint8_t> out;
    out.reserve(kHeaderBytes + kChunkHeaderBytes + jsonChunk + binChunk);
    appendU32(out, kMagic);
    appendU32(out, 2);
    appendU32(out, uint32_t(kHeaderBytes + kChunkHeaderBytes + jsonChunk + binChunk));
    appendU32(out, uint32_t(jsonChunk));
    appendU32(out, kJsonChunk);
    out.insert(out.end(), json.begin(), json.end());
    out.resize(out.size() + jsonChunk - json.size(), ' ');
    if (binSize != 0) {
        appendU32(out, uint32_t(padded(binSize)));
        appendU32(out, kBinChunk);
        out.insert(out.end(), bin, bin + binSize);
        out.resize(out.size() + padded(binSize) - binSize, 0);
    }
    return out;
}

}  // namespace patina::gltf
