#include "files/regular_file.h"

#include <cerrno>
#include <cstring>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "files/input_error.h"

namespace patina {

RegularFile::RegularFile(const std::filesystem::path& path, int flags, std::string name)
    : name_(std::move(name)) {
    // O_NONBLOCK: opening a FIFO for reading would otherwise wait for a writer that never
    // comes; for a regular file (all that is read past the check below) it changes nothing.
    fd_ = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK | flags);
    if (fd_ < 0) {
        throw InputError(name_ + ": cannot open: " + std::strerror(errno));
    }
    struct stat info {};
    if (::fstat(fd_, &info) != 0 || !S_ISREG(info.st_mode)) {
        ::close(fd_);
        throw InputError(name_ + (S_ISDIR(info.st_mode) ? ": a folder, not a file" : ": not a regular file"));
    }
    size_ = uint64_t(info.st_size);
}

RegularFile::~RegularFile() {
    ::close(fd_);
}

void RegularFile::requireAtMost(uint64_t maxBytes, const std::string& kind) const {
    if (size_ > maxBytes) {
        throw InputError(name_ + ": the file is " + mebibytes(size_) + "; " + kind + " are limited to " +
                         mebibytes(maxBytes));
    }
}

std::vector<uint8_t> RegularFile::readAll() const {
    std::vector<uint8_t> bytes(size_);
    size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::pread(fd_, bytes.data() + done, bytes.size() - done, off_t(done));
        if (n < 0 && errno == EINTR) {
            continue;
        }
        if (n <= 0) {   // a file that shrank while being read is as bad as an unreadable one
            throw InputError(name_ + ": cannot read: " + (n < 0 ? std::strerror(errno) : "file shrank"));
        }
        done += size_t(n);
    }
    return bytes;
}

std::string mebibytes(uint64_t bytes) {
    return std::to_string((bytes + (uint64_t(1) << 20) - 1) >> 20) + " MiB";
}

}  // namespace patina
