#pragma once
// Whole files in and out: for outputs Patina writes and files it reads back whole (for a user's
// input, io/regular_file.h checks type and size through one descriptor).
#include <cstdint>
#include <filesystem>
#include <vector>

namespace patina {

std::vector<uint8_t> readFileBytes(const std::filesystem::path& path);   // throws std::runtime_error

// Writes all or nothing: a temporary file beside the target, flushed, then renamed over it.
// Throws std::runtime_error naming the path on any failure and leaves the target untouched.
void writeFileAtomic(const std::filesystem::path& path, const std::vector<uint8_t>& bytes);

}  // namespace patina
