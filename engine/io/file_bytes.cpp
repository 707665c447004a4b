#include "io/file_bytes.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace patina {

namespace {
std::string systemError(const std::string& what, const std::filesystem::path& path) {
    return what + " '" + path.string() + "': " + std::strerror(errno);
}
}  // namespace

std::vector<uint8_t> readFileBytes(const std::filesystem::path& path) {
    std::ifstream file(path, std::ios::binary);
    if (!file) {
        throw std::runtime_error(systemError("cannot open", path));
    }
    std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(file)),
                               std::istreambuf_iterator<char>());
    if (file.bad()) {
        throw std::runtime_error(systemError("cannot read", path));
    }
    return bytes;
}

void writeFileAtomic(const std::filesystem::path& path, const std::vector<uint8_t>& bytes) {
    const std::filesystem::path directory =
        path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
    std::string pattern = (directory / ("." + path.filename().string() + ".tmp-XXXXXX")).string();
    const int fd = mkstemp(pattern.data());
    if (fd < 0) {
        throw std::runtime_error(systemError("cannot create a temporary file beside", path));
    }
    size_t written = 0;
    while (written < bytes.size()) {
        const ssize_t n = ::write(fd, bytes.data() + written, bytes.size() - written);
        if (n < 0 && errno == EINTR) {
            continue;
        }
        if (n <= 0) {
            const std::string message = systemError("cannot write", path);
            ::close(fd);
            ::unlink(pattern.c_str());
            throw std::runtime_error(message);
        }
        written += size_t(n);
    }
    // mkstemp makes the file 0600; give it the usual permissions of a new file.
    const mode_t mask = ::umask(0);
    ::umask(mask);
    ::fchmod(fd, 0666 & ~mask);
    const bool synced = ::fsync(fd) == 0;
    const bool closed = ::close(fd) == 0;
    if (!synced || !closed) {
        const std::string message = systemError("cannot flush", path);
        ::unlink(pattern.c_str());
        throw std::runtime_error(message);
    }
    if (std::rename(pattern.c_str(), path.c_str()) != 0) {
        const std::string message = systemError("cannot replace", path);
        ::unlink(pattern.c_str());
        throw std::runtime_error(message);
    }
    // The rename is durable once the folder is flushed too. Best effort: the new file is
    // complete and in place already, and some file systems refuse fsync on a folder.
    if (const int folder = ::open(directory.c_str(), O_RDONLY | O_DIRECTORY); folder >= 0) {
        ::fsync(folder);
        ::close(folder);
    }
}

}  // namespace patina
