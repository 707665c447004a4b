#include "files/file_bytes.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>
#include <system_error>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace patina {

namespace {
// The error with its errno kept (std::system_error), so a caller can say what went wrong in
// its own words; what() reads "<what> '<path>': <strerror>" as before.
std::system_error systemError(const std::string& what, const std::filesystem::path& path) {
    const int code = errno;
    std::string message = what;   // appended, not what + ...: GCC 12 warns falsely (-Wrestrict)
    message += " '";
    message += path.string();
    message += "'";
    return std::system_error(code, std::generic_category(), message);
}
}  // namespace

std::vector<uint8_t> readFileBytes(const std::filesystem::path& path) {
    std::ifstream file(path, std::ios::binary);
    if (!file) {
        throw systemError("cannot open", path);
    }
    std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(file)),
                               std::istreambuf_iterator<char>());
    if (file.bad()) {
        throw systemError("cannot read", path);
    }
    return bytes;
}

void writeFileAtomic(const std::filesystem::path& path, const std::vector<uint8_t>& bytes) {
    const std::filesystem::path directory =
        path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
    std::string pattern = (directory / ("." + path.filename().string() + ".tmp-XXXXXX")).string();
    const int fd = mkstemp(pattern.data());
    if (fd < 0) {
        // The folder's absence is what a user can act on; the errno (ENOENT) is kept for callers.
        const int code = errno;
        std::error_code ignored;
        if (code == ENOENT && !std::filesystem::is_directory(directory, ignored)) {
            std::string message = "the folder '";
            message += directory.string();
            message += "' does not exist, so '";
            message += path.string();
            message += "' cannot be written";
            throw std::system_error(code, std::generic_category(), message);
        }
        throw systemError("cannot create a temporary file beside", path);
    }
    size_t written = 0;
    while (written < bytes.size()) {
        const ssize_t n = ::write(fd, bytes.data() + written, bytes.size() - written);
        if (n < 0 && errno == EINTR) {
            continue;
        }
        if (n <= 0) {
            const std::system_error failure = systemError("cannot write", path);
            ::close(fd);
            ::unlink(pattern.c_str());
            throw failure;
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
        const std::system_error failure = systemError("cannot flush", path);
        ::unlink(pattern.c_str());
        throw failure;
    }
    if (std::rename(pattern.c_str(), path.c_str()) != 0) {
        const std::system_error failure = systemError("cannot replace", path);
        ::unlink(pattern.c_str());
        throw failure;
    }
    // The rename is durable once the folder is flushed too. Best effort: the new file is
    // complete and in place already, and some file systems refuse fsync on a folder.
    if (const int folder = ::open(directory.c_str(), O_RDONLY | O_DIRECTORY); folder >= 0) {
        ::fsync(folder);
        ::close(folder);
    }
}

}  // namespace patina
