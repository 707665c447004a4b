#pragma once
#include <optional>
#include <string>
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

// "a, b, c": the names of `values`, in their order, for messages and help.
template <typename Enum, size_t N>
std::string enumNameList(const Enum (&values)[N], std::string_view (*nameOf)(Enum)) {
    std::string names;
    for (Enum value : values) {
        names += (names.empty() ? "" : ", ") + std::string(nameOf(value));
    }
    return names;
}

}  // namespace patina
