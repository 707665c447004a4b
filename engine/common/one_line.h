#pragma once
// A library's error message (tinygltf's, OpenEXR's) as one line, to follow "FILE: " in ours.
#include <algorithm>
#include <string>

namespace patina {

// `text` without its trailing line ends and spaces, each line end inside it made `separator`.
inline std::string oneLine(std::string text, char separator) {
    while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) {
        text.pop_back();
    }
    std::replace(text.begin(), text.end(), '\n', separator);
    return text;
}

}  // namespace patina
