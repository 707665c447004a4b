#include "views/text_match.h"

#include <algorithm>
#include <cctype>

namespace patina::editor {

std::string lowered(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return text;
}

bool containsAnyCase(const std::string& text, const std::string& part) {
    return lowered(text).find(lowered(part)) != std::string::npos;
}

}  // namespace patina::editor
