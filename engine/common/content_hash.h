#pragma once
// A key for what a file holds: the same bytes give the same key, in any process.
#include <cstddef>
#include <cstdint>

namespace patina {

// FNV-1a, 64 bits, continuing from `hash`: a cache key, not a defence against anyone.
inline uint64_t hashBytes(const void* data, size_t size, uint64_t hash = 0xcbf29ce484222325ull) {
    const auto* bytes = static_cast<const uint8_t*>(data);
    for (size_t i = 0; i < size; ++i) {
        hash = (hash ^ bytes[i]) * 0x100000001b3ull;
    }
    return hash;
}

}  // namespace patina
