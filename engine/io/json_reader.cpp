#include "io/json_reader.h"

#include <cmath>
#include <sstream>

#include "files/regular_file.h"

namespace patina {

namespace {
std::string typeName(const Json& value) {
    return value.is_number() ? "number" : value.type_name();
}

std::string formatNumber(double value) {
    std::ostringstream out;
    out << value;
    return out.str();
}

// At most `length` bytes and "...", cut between UTF-8 characters.
std::string cut(std::string text, size_t length) {
    if (text.size() > length) {
        while (length > 0 && (uint8_t(text[length]) & 0xC0) == 0x80) {
            --length;
        }
        text = text.substr(0, length) + "...";
    }
    return text;
}
}  // namespace

void failAt(const std::string& source, const std::string& pointer, const std::string& what) {
    throw InputError(source + ": " + (pointer.empty() ? "/" : pointer) + ": " + what);
}

std::string shortJson(const Json& value) {
    return cut(value.dump(), 60);
}

Json parseJsonText(const std::string& text, const std::string& source) {
    if (text.size() > kMaxJsonFileBytes) {
        throw InputError(source + ": " + mebibytes(text.size()) + " of JSON; Patina reads at most " +
                         mebibytes(kMaxJsonFileBytes));
    }
    const Json::parser_callback_t limitNesting = [&](int depth, Json::parse_event_t event, Json&) {
        if ((event == Json::parse_event_t::object_start || event == Json::parse_event_t::array_start) &&
            depth >= kMaxJsonNesting) {
            throw InputError(source + ": JSON nested deeper than " + std::to_string(kMaxJsonNesting) +
                             " levels");
        }
        return true;
    };
    try {
        return Json::parse(text, limitNesting);
    } catch (const Json::parse_error& error) {
        // Turn nlohmann's byte offset into the line and column an editor shows.
        const size_t end = std::min(text.size(), error.byte > 0 ? error.byte - 1 : 0);
        size_t line = 1, column = 1;
        for (size_t i = 0; i < end; ++i) {
            if (text[i] == '\n') {
                ++line;
                column = 1;
            } else {
                ++column;
            }
        }
        std::string what = error.what();
        // Drop nlohmann's "[json.exception.parse_error.101] parse error at line 1, column 2: ".
        if (const size_t colon = what.find(": "); colon != std::string::npos) {
            what = what.substr(colon + 2);
        }
        // The message quotes the token, which may be megabytes long.
        throw InputError(source + ":" + std::to_string(line) + ":" + std::to_string(column) +
                         ": invalid JSON: " + cut(what, 200));
    } catch (const Json::out_of_range& error) {
        // A number beyond a double's range ("1e400"), which nlohmann reports without a place.
        const std::string what = error.what();
        throw InputError(source + ": invalid JSON: " + cut(what.substr(what.find("] ") + 2), 200));
    }
}

bool opensLikeJson(std::string_view text, std::string_view openers) {
    const size_t first = text.find_first_not_of(" \t\r\n");
    return text.substr(0, 3) == "\xEF\xBB\xBF" ||
           (first != std::string_view::npos && openers.find(text[first]) != std::string_view::npos);
}

Json readJsonFile(const std::filesystem::path& path) {
    const RegularFile file(path, 0, path.string());
    file.requireAtMost(kMaxJsonFileBytes, "Patina's JSON files");
    const std::vector<uint8_t> bytes = file.readAll();
    // Another kind of file (a model, an image, an .obj) is named as such, not as a JSON syntax
    // error at its first byte.
    const std::string text(bytes.begin(), bytes.end());
    if (!opensLikeJson(text, "{[")) {
        const bool empty = text.find_first_not_of(" \t\r\n") == std::string::npos;
        throw InputError(path.string() + ": not a JSON file" + (empty ? " (it is empty)" : "") +
                         ": Patina's materials and scenes are JSON");
    }
    return parseJsonText(text, path.string());
}

JsonObjectReader::JsonObjectReader(const Json& value, std::string pointer, std::string source)
    : object_(value), pointer_(std::move(pointer)), source_(std::move(source)) {
    if (!object_.is_object()) {
        failAt(source_, pointer_, "expected an object, got " + typeName(object_));
    }
}

bool JsonObjectReader::has(const char* key) const {
    return object_.contains(key);
}

const Json* JsonObjectReader::find(const char* key) {
    auto it = object_.find(key);
    if (it == object_.end()) {
        return nullptr;
    }
    read_.insert(key);
    return &*it;
}

const Json* JsonObjectReader::child(const char* key) {
    return find(key);
}

const Json& JsonObjectReader::required(const char* key) {
    const Json* value = find(key);
    if (!value) {
        failAt(source_, pointer_, std::string("missing required key '") + key + "'");
    }
    return *value;
}

void JsonObjectReader::fail(const char* key, const std::string& what) const {
    failAt(source_, pointerOf(key), what);
}

float JsonObjectReader::checkedNumber(const Json& value, const std::string& pointer,
                                      Range range) const {
    if (!value.is_number()) {
        failAt(source_, pointer, "expected a number, got " + typeName(value));
    }
    const double number = value.get<double>();
    // Finite as a double is not enough: the engine works in float.
    if (!std::isfinite(number) || !std::isfinite(float(number))) {
        failAt(source_, pointer, "number " + formatNumber(number) + " is not finite in float");
    }
    if (number < range.min || number > range.max) {
        failAt(source_, pointer, "value " + formatNumber(number) + " is outside [" +
                                     formatNumber(range.min) + ", " + formatNumber(range.max) + "]");
    }
    return float(number);
}

float JsonObjectReader::number(const char* key, float fallback, Range range) {
    const Json* value = find(key);
    return value ? checkedNumber(*value, pointerOf(key), range) : fallback;
}

int JsonObjectReader::integer(const char* key, int fallback, Range range) {
    const Json* value = find(key);
    if (!value) {
        return fallback;
    }
    // 1.0 is an integer too, as JSON Schema counts it.
    if (!value->is_number() || (value->is_number_float() &&
                                std::trunc(value->get<double>()) != value->get<double>())) {
        fail(key, "expected an integer, got " + (value->is_number() ? value->dump() : typeName(*value)));
    }
    return int(checkedNumber(*value, pointerOf(key), range));
}

bool JsonObjectReader::boolean(const char* key, bool fallback) {
    const Json* value = find(key);
    if (!value) {
        return fallback;
    }
    if (!value->is_boolean()) {
        fail(key, "expected true or false, got " + typeName(*value));
    }
    return value->get<bool>();
}

std::string JsonObjectReader::string(const char* key, const std::string& fallback) {
    const Json* value = find(key);
    if (!value) {
        return fallback;
    }
    if (!value->is_string()) {
        fail(key, "expected a string, got " + typeName(*value));
    }
    return value->get<std::string>();
}

glm::vec3 JsonObjectReader::vec3(const char* key, glm::vec3 fallback, Range range) {
    const Json* value = find(key);
    if (!value) {
        return fallback;
    }
    if (!value->is_array() || value->size() != 3) {
        fail(key, "expected an array of 3 numbers, got " +
                      (value->is_array() ? std::to_string(value->size()) + " elements"
                                         : typeName(*value)));
    }
    glm::vec3 result;
    for (int i = 0; i < 3; ++i) {
        result[i] = checkedNumber((*value)[size_t(i)], pointerOf(key) + "/" + std::to_string(i),
                                  range);
    }
    return result;
}

int JsonObjectReader::checkFormatAndVersion(const char* expectedFormat, int supportedVersion) {
    if (!has("format") && has("asset")) {   // glTF 2.0's one required key: a model, not Patina's file
        fail("format", std::string("missing: this is a glTF model, not a ") + expectedFormat +
                           " file (a model is drawn with --mesh, or opened in the editor)");
    }
    const Json& format = required("format");
    if (!format.is_string() || format.get<std::string>() != expectedFormat) {
        fail("format", std::string("expected \"") + expectedFormat + "\", got " + shortJson(format));
    }
    required("version");
    const int version = integer("version", 0, {1, 1e9});
    if (version > supportedVersion) {
        fail("version", "version " + std::to_string(version) +
                            " is newer than this Patina reads (up to " +
                            std::to_string(supportedVersion) + ")");
    }
    return version;
}

Json JsonObjectReader::keepUnknown(std::vector<std::string>& warnings) const {
    Json entries = Json::object();
    for (auto it = object_.begin(); it != object_.end(); ++it) {
        if (!read_.count(it.key())) {
            warnings.push_back(source_ + ": " + pointerOf(it.key().c_str()) + ": unknown key '" +
                               it.key() + "' (kept, not used)");
            entries[it.key()] = it.value();
        }
    }
    return entries;
}

}  // namespace patina
