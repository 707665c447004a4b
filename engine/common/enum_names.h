#pragma once
#include <optional>
#include <string_view>

namespace patina {

// Inverse of a `nameOf` switch: the value among `values` whose name is `name`.
template <typename Enum, size_t N>
std::optional<Enum> enumFromName(std::string_view name, const Enum (&values)[N],
                                 std::string_view (*nameOf)(Enum)) {
    for (Enum value : values) {
        if (nameOf(value) == name) {
            return value;
        }
    }
    return std::nullopt;
}

}  // namespace patina
