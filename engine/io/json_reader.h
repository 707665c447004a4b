#pragma once
#include <filesystem>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>

#include "files/input_error.h"
#include "scene/json_value.h"

namespace patina {

// Patina's JSON files are small. Larger text is refused before it costs memory, and deeper
// nesting before it costs stack: nlohmann copies, compares and dumps values recursively.
constexpr size_t kMaxJsonFileBytes = size_t(4) << 20;
constexpr int kMaxJsonNesting = 64;

// Parses JSON text; a syntax error becomes an InputError "SOURCE:LINE:COLUMN: ...", text over
// the limits an InputError "SOURCE: ...".
Json parseJsonText(const std::string& text, const std::string& source);
// Whether `text` opens as JSON with one of `openers` ("{", "{["): its first character past
// white space is one of them, or it starts with a UTF-8 byte order mark (the parser's to judge).
// False for a file of another kind (a model, an image, an .obj) and for an empty one.
bool opensLikeJson(std::string_view text, std::string_view openers);
// Reads and parses a regular file; a missing, unreadable or too large one is an InputError too.
Json readJsonFile(const std::filesystem::path& path);

// A value as JSON for a message, cut to about 60 characters.
std::string shortJson(const Json& value);

// Inclusive bounds for a number; the defaults accept any finite float.
struct Range {
    double min = -3.4e38;
    double max = 3.4e38;
};

// Reads one JSON object field by field with checks, reporting errors as
// "SOURCE: /json/pointer: what is wrong". Keys never read are kept by keepUnknown().
class JsonObjectReader {
public:
    JsonObjectReader(const Json& value, std::string pointer, std::string source);

    bool has(const char* key) const;
    float number(const char* key, float fallback, Range range = {});
    int integer(const char* key, int fallback, Range range = {});
    bool boolean(const char* key, bool fallback);
    std::string string(const char* key, const std::string& fallback);
    glm::vec3 vec3(const char* key, glm::vec3 fallback, Range range = {});
    const Json& required(const char* key);
    // A child value, marked as read; its pointer is pointerOf(key).
    const Json* child(const char* key);
    std::string pointerOf(const char* key) const { return pointer_ + "/" + key; }
    const std::string& source() const { return source_; }

    // The keys not read so far with their values, in file order, kept so that saving can
    // write them back; each is warned about: "SOURCE: /pointer: unknown key 'x' (kept, not used)".
    Json keepUnknown(std::vector<std::string>& warnings) const;
    [[noreturn]] void fail(const char* key, const std::string& what) const;

    // Requires "format": expectedFormat and "version" <= supportedVersion; returns the version.
    int checkFormatAndVersion(const char* expectedFormat, int supportedVersion);

private:
    const Json* find(const char* key);
    float checkedNumber(const Json& value, const std::string& pointer, Range range) const;

    const Json& object_;
    std::string pointer_;
    std::string source_;
    std::set<std::string> read_;
};

// An error message for `pointer` inside `source`.
[[noreturn]] void failAt(const std::string& source, const std::string& pointer,
                         const std::string& what);

}  // namespace patina
