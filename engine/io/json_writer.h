#pragma once
#include <string>

#include "io/json_reader.h"

namespace patina {

// Indented JSON with short arrays of numbers on one line ("baseColor": [0.8, 0.25, 0.15]),
// as people write these files by hand. Ends with a newline.
std::string prettyJson(const Json& json);

}  // namespace patina
