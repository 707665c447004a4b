#pragma once
// Reading a user's file through one descriptor, so that the type and size checked are those
// of the file read: a device (/dev/zero), a FIFO or a folder is refused before any read.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace patina {

class RegularFile {
public:
    // Opens `path` with O_RDONLY | `flags`; `name` starts every message. Throws InputError
    // "NAME: cannot open: ..." or "NAME: not a regular file".
    RegularFile(const std::filesystem::path& path, int flags, std::string name);
    ~RegularFile();
    RegularFile(const RegularFile&) = delete;
    RegularFile& operator=(const RegularFile&) = delete;

    uint64_t size() const { return size_; }
    // Throws InputError "NAME: the file is 6 MiB; KIND are limited to 4 MiB" when larger.
    void requireAtMost(uint64_t maxBytes, const std::string& kind) const;
    // All size() bytes; InputError "NAME: cannot read: ..." if the file shrank or failed.
    std::vector<uint8_t> readAll() const;

private:
    int fd_ = -1;
    uint64_t size_ = 0;
    std::string name_;
};

// "3 MiB", rounded up: for messages about limits.
std::string mebibytes(uint64_t bytes);

}  // namespace patina
