#pragma once
#include <nlohmann/json.hpp>

namespace patina {

// Ordered: files keep their key order when Patina writes them back.
using Json = nlohmann::ordered_json;

}  // namespace patina
