#include "picture/png_text.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <stdexcept>
#include <string_view>

#include "files/input_error.h"
#include "io/json_reader.h"
#include "image/png_chunks.h"
#include "files/regular_file.h"
#include "io/scene_file.h"

namespace patina {

namespace {

constexpr uint32_t kMaxChunkLength = 0x7FFFFFFFu;   // PNG spec 5.3: lengths fit in 31 bits
constexpr size_t kMaxKeywordLength = 79;

bool isUtf8(std::string_view text) {
    static constexpr uint32_t kSmallest[] = {0, 0x80, 0x800, 0x10000};   // no overlong forms
    size_t i = 0;
    while (i < text.size()) {
        const auto lead = uint8_t(text[i]);
        size_t extra = 0;
        uint32_t code = lead;
        if (lead < 0x80) {
            ++i;
            continue;
        } else if ((lead & 0xE0) == 0xC0) {
            extra = 1, code = lead & 0x1Fu;
        } else if ((lead & 0xF0) == 0xE0) {
            extra = 2, code = lead & 0x0Fu;
        } else if ((lead & 0xF8) == 0xF0) {
            extra = 3, code = lead & 0x07u;
        } else {
            return false;
        }
        if (text.size() - i <= extra) {
            return false;
        }
        for (size_t k = 1; k <= extra; ++k) {
            const auto next = uint8_t(text[i + k]);
            if ((next & 0xC0) != 0x80) {
                return false;
            }
            code = code << 6 | (next & 0x3Fu);
        }
        if (code < kSmallest[extra] || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF)) {
            return false;
        }
        i += extra + 1;
    }
    return true;
}

std::string latin1ToUtf8(std::string_view text) {
    std::string out;
    for (const char c : text) {
        const auto byte = uint8_t(c);
        if (byte < 0x80) {
            out.push_back(c);
        } else {
            out.push_back(char(0xC0 | byte >> 6));
            out.push_back(char(0x80 | (byte & 0x3F)));
        }
    }
    return out;
}

// PNG spec 11.3.4.2: printable Latin-1, no leading, trailing or consecutive spaces.
void checkKeyword(const std::string& keyword) {
    bool valid = !keyword.empty() && keyword.size() <= kMaxKeywordLength &&
                 keyword.front() != ' ' && keyword.back() != ' ' &&
                 keyword.find("  ") == std::string::npos;
    for (const char c : keyword) {
        const auto byte = uint8_t(c);
        valid = valid && ((byte >= 32 && byte <= 126) || byte >= 161);
    }
    if (!valid) {
        throw std::invalid_argument("invalid PNG text keyword \"" + keyword +
                                    "\": 1 to 79 printable Latin-1 characters, no leading, "
                                    "trailing or double spaces");
    }
}

std::vector<uint8_t> internationalTextChunk(const std::string& keyword, const std::string& text) {
    checkKeyword(keyword);
    if (!isUtf8(text)) {
        throw std::invalid_argument("PNG text \"" + keyword + "\" is not valid UTF-8");
    }
    // Keyword, NUL, compression flag 0, method 0, empty language tag and translated keyword.
    std::vector<uint8_t> data(keyword.begin(), keyword.end());
    data.insert(data.end(), {0, 0, 0, 0, 0});
    data.insert(data.end(), text.begin(), text.end());
    if (data.size() > kMaxChunkLength) {
        throw std::invalid_argument("PNG text \"" + keyword + "\" is too long for one chunk");
    }
    std::vector<uint8_t> chunk;
    appendPngChunk(chunk, "iTXt", data.data(), data.size());
    return chunk;
}

[[noreturn]] void malformed(size_t offset, const std::string& what) {
    throw InputError("malformed PNG at byte " + std::to_string(offset) + ": " + what);
}

// One chunk's data; `offset` is where the chunk starts, for messages.
struct Chunk {
    std::string type;
    std::string_view data;
    size_t offset;
};

std::string_view keywordOf(const Chunk& chunk) {
    const size_t end = chunk.data.find('\0');
    if (end == std::string_view::npos || end == 0 || end > kMaxKeywordLength) {
        malformed(chunk.offset, chunk.type + " chunk without a keyword of 1 to 79 bytes");
    }
    return chunk.data.substr(0, end);
}

void readTextChunk(const Chunk& chunk, std::map<std::string, std::string>& entries) {
    const std::string_view keyword = keywordOf(chunk);
    const std::string_view text = chunk.data.substr(keyword.size() + 1);
    entries.emplace(std::string(keyword), latin1ToUtf8(text));
}

// iTXt: keyword NUL, compression flag, compression method, language NUL, translated keyword
// NUL, text (PNG spec 11.3.4.5).
void readInternationalTextChunk(const Chunk& chunk, std::map<std::string, std::string>& entries) {
    const std::string_view keyword = keywordOf(chunk);
    const std::string_view rest = chunk.data.substr(keyword.size() + 1);
    const size_t languageEnd = rest.size() < 2 ? std::string_view::npos : rest.find('\0', 2);
    const size_t translatedEnd =
        languageEnd == std::string_view::npos ? languageEnd : rest.find('\0', languageEnd + 1);
    if (translatedEnd == std::string_view::npos) {
        malformed(chunk.offset, "iTXt chunk '" + std::string(keyword) +
                                    "' ends before its language tag and translated keyword");
    }
    const auto compressed = uint8_t(rest[0]);
    if (compressed > 1) {
        malformed(chunk.offset, "iTXt chunk '" + std::string(keyword) +
                                    "' has an unknown compression flag " + std::to_string(compressed));
    }
    if (compressed == 1) {
        return;   // zlib text: not needed by Patina, skipped
    }
    const std::string_view text = rest.substr(translatedEnd + 1);
    if (!isUtf8(text)) {
        malformed(chunk.offset, "iTXt chunk '" + std::string(keyword) + "' is not valid UTF-8");
    }
    entries.emplace(std::string(keyword), std::string(text));
}

bool isChunkType(const std::string& type) {
    for (const char c : type) {
        if (!((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'))) {
            return false;
        }
    }
    return true;
}

}  // namespace

std::vector<uint8_t> encodePngWithText(const LdrImage& image,
                                       const std::vector<std::pair<std::string, std::string>>& text) {
    std::vector<uint8_t> chunks;
    for (const auto& [keyword, value] : text) {
        const std::vector<uint8_t> chunk = internationalTextChunk(keyword, value);
        chunks.insert(chunks.end(), chunk.begin(), chunk.end());
    }
    std::vector<uint8_t> png = encodePng(image);
    // The signature, then IHDR: length, type, data, CRC.
    const size_t afterHeader = kPngSignature.size() + 12 + readBigEndian32(png.data() + kPngSignature.size());
    png.insert(png.begin() + std::ptrdiff_t(afterHeader), chunks.begin(), chunks.end());
    return png;
}

std::map<std::string, std::string> readPngText(const std::vector<uint8_t>& bytes) {
    if (bytes.size() < kPngSignature.size() ||
        !std::equal(kPngSignature.begin(), kPngSignature.end(), bytes.begin())) {
        throw InputError("not a PNG file (it does not start with the PNG signature)");
    }
    std::map<std::string, std::string> entries;
    size_t at = kPngSignature.size();
    for (bool first = true;; first = false) {
        const size_t left = bytes.size() - at;
        if (left < 12) {
            throw InputError("truncated PNG: the file ends at byte " + std::to_string(bytes.size()) +
                             " before the IEND chunk");
        }
        const uint32_t length = readBigEndian32(&bytes[at]);
        const std::string type(bytes.begin() + std::ptrdiff_t(at + 4),
                               bytes.begin() + std::ptrdiff_t(at + 8));
        if (!isChunkType(type)) {
            malformed(at, "not a chunk type (4 ASCII letters expected)");
        }
        if (length > kMaxChunkLength || length > left - 12) {
            throw InputError("truncated PNG: chunk '" + type + "' at byte " + std::to_string(at) +
                             " declares " + std::to_string(length) + " bytes of data but only " +
                             std::to_string(left - 12) + " remain");
        }
        const uint8_t* data = &bytes[at + 8];
        const uint32_t stored = readBigEndian32(data + length);
        const uint32_t computed = pngCrc(&bytes[at + 4], size_t(length) + 4);
        if (stored != computed) {
            char hex[48];
            std::snprintf(hex, sizeof hex, " (stored %08x, computed %08x)", stored, computed);
            malformed(at, "chunk '" + type + "' fails its CRC-32 check" + hex);
        }
        if (first && type != "IHDR") {
            malformed(at, "the first chunk is '" + type + "', not IHDR");
        }
        const Chunk chunk{type, {reinterpret_cast<const char*>(data), length}, at};
        if (type == "IEND") {
            return entries;
        } else if (type == "tEXt") {
            readTextChunk(chunk, entries);
        } else if (type == "iTXt") {
            readInternationalTextChunk(chunk, entries);
        }
        at += 12 + size_t(length);
    }
}

std::optional<Scene> sceneFromPngBytes(const std::vector<uint8_t>& bytes, const std::string& source,
                                       std::vector<std::string>& warnings) {
    std::map<std::string, std::string> entries;
    try {
        entries = readPngText(bytes);
    } catch (const InputError& error) {
        throw InputError(source + ": " + error.what());
    }
    const auto found = entries.find(kSceneTextKeyword);
    if (found == entries.end()) {
        return std::nullopt;
    }
    const std::string where = source + " (" + kSceneTextKeyword + ")";
    const Json json = parseJsonText(found->second, where);
    // A relative path would make the PNG depend on, and read, files beside it. A model is
    // named by the absolute path a screenshot of it writes (Scene::meshFile), and only a
    // .gltf or .glb is read there, within its own folder, as any model is; an image replacing
    // one of its maps likewise, and only a PNG or JPEG is decoded there.
    if (json.is_object() && json.contains("material") && json["material"].is_string()) {
        failAt(where, "/material", "an embedded scene must hold its material inline");
    }
    if (json.is_object() && json.contains("mesh") && json["mesh"].is_string()) {
        const std::string mesh = json["mesh"].get<std::string>();
        if (!meshKindFromName(mesh) && !std::filesystem::path(mesh).is_absolute()) {
            failAt(where, "/mesh",
                   "an embedded scene must use a built-in mesh (\"sphere\" or \"torus\") or a model's absolute path");
        }
    }
    const Json* edits = json.is_object() && json.contains("modelMaterials") ? &json["modelMaterials"] : nullptr;
    for (size_t i = 0; edits && edits->is_array() && i < edits->size(); ++i) {
        const Json& edit = (*edits)[i];
        if (!edit.is_object() || !edit.contains("mapsReplaced") || !edit["mapsReplaced"].is_object()) {
            continue;
        }
        for (const auto& [key, image] : edit["mapsReplaced"].items()) {
            if (image.is_string() && !std::filesystem::path(image.get<std::string>()).is_absolute()) {
                failAt(where, "/modelMaterials/" + std::to_string(i) + "/mapsReplaced/" + key,
                       "an embedded scene must name a replacing image by its absolute path");
            }
        }
    }
    return sceneFromJson(json, where, {}, warnings);
}

std::optional<Scene> sceneFromPng(const std::filesystem::path& path,
                                  std::vector<std::string>& warnings) {
    const RegularFile file(path, 0, path.string());
    file.requireAtMost(kMaxPngBytes, "PNGs with a scene");
    return sceneFromPngBytes(file.readAll(), path.string(), warnings);
}

Scene screenshotScene(const std::filesystem::path& path, std::vector<std::string>& warnings) {
    std::optional<Scene> scene = sceneFromPng(path, warnings);
    if (!scene) {
        throw InputError(path.string() + ": this PNG holds no scene (only Patina's screenshots do)");
    }
    return std::move(*scene);
}

}  // namespace patina
