#pragma once
// Whole files in and out: for outputs Patina writes and files it reads back whole (for a user's
// input, files/regular_file.h checks type and size through one descriptor).
#include <cstdint>
#include <filesystem>
#include <vector>

namespace patina {

// Both throw std::system_error (a std::runtime_error) naming the path, with the errno as its code.
std::vector<uint8_t> readFileBytes(const std::filesystem::path& path);

// Writes all or nothing: a temporary file beside the target, flushed, then renamed over it.
// On any failure, throws and leaves the target untouched.
void writeFileAtomic(const std::filesystem::path& path, const std::vector<uint8_t>& bytes);

}  // namespace patina
