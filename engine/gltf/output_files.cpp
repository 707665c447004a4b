#include "gltf/output_files.h"

#include <algorithm>
#include <cctype>

#include "files/file_bytes.h"

namespace patina {

std::string base64(const std::vector<uint8_t>& bytes) {
    static const char digits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string text;
    text.reserve((bytes.size() + 2) / 3 * 4);
    for (size_t i = 0; i < bytes.size(); i += 3) {
        const size_t n = std::min<size_t>(3, bytes.size() - i);
        uint32_t group = uint32_t(bytes[i]) << 16;
        group |= n > 1 ? uint32_t(bytes[i + 1]) << 8 : 0;
        group |= n > 2 ? uint32_t(bytes[i + 2]) : 0;
        for (size_t k = 0; k < 4; ++k) {
            text += k <= n ? digits[(group >> (18 - 6 * k)) & 63] : '=';
        }
    }
    return text;
}

std::string uriOfFileName(const std::string& name) {
    static const char hex[] = "0123456789ABCDEF";
    std::string uri;
    for (const unsigned char c : name) {
        if (std::isalnum(c) || c == '-' || c == '.' || c == '_' || c == '~') {
            uri += char(c);
        } else {
            uri += {'%', hex[c >> 4], hex[c & 15]};
        }
    }
    return uri;
}

void writeOutputFiles(const std::vector<OutputFile>& files) {
    std::vector<std::filesystem::path> written;
    try {
        for (const OutputFile& file : files) {
            writeFileAtomic(file.path, file.bytes);
            written.push_back(file.path);
        }
    } catch (...) {
        for (const std::filesystem::path& done : written) {
            std::error_code ignored;
            std::filesystem::remove(done, ignored);
        }
        throw;
    }
}

}  // namespace patina
