#include "io/json_writer.h"

namespace patina {

namespace {
bool isNumberRow(const Json& json) {
    if (!json.is_array() || json.empty() || json.size() > 4) {
        return false;
    }
    for (const Json& element : json) {
        if (!element.is_number()) {
            return false;
        }
    }
    return true;
}

void write(const Json& json, int depth, std::string& out) {
    const std::string indent(size_t(depth + 1) * 2, ' ');
    const std::string closingIndent(size_t(depth) * 2, ' ');
    if (json.is_object() && !json.empty()) {
        out += "{\n";
        size_t i = 0;
        for (auto it = json.begin(); it != json.end(); ++it, ++i) {
            out += indent + Json(it.key()).dump() + ": ";
            write(it.value(), depth + 1, out);
            out += i + 1 < json.size() ? ",\n" : "\n";
        }
        out += closingIndent + "}";
    } else if (json.is_array() && !json.empty() && !isNumberRow(json)) {
        out += "[\n";
        for (size_t i = 0; i < json.size(); ++i) {
            out += indent;
            write(json[i], depth + 1, out);
            out += i + 1 < json.size() ? ",\n" : "\n";
        }
        out += closingIndent + "]";
    } else {
        // Scalars, empty containers and number rows: nlohmann's compact form, spaced.
        std::string compact = json.dump();
        if (isNumberRow(json)) {
            std::string spaced;
            for (char c : compact) {
                spaced += c;
                if (c == ',') {
                    spaced += ' ';
                }
            }
            compact = spaced;
        }
        out += compact;
    }
}
}  // namespace

std::string prettyJson(const Json& json) {
    std::string out;
    write(json, 0, out);
    out += "\n";
    return out;
}

}  // namespace patina
