#pragma once
// How many times a file is read, by this process or another (the CLI a test runs), counted
// through inotify: what shows that opening a model reads its file once. An open that reads
// nothing (the editor's check that a file it will load on a worker is there) is no read.
#include <filesystem>
#include <stdexcept>
#include <string>

#include <sys/inotify.h>
#include <unistd.h>

namespace patina::test {

class FileReads {
public:
    explicit FileReads(const std::filesystem::path& file) : fd_(inotify_init1(IN_NONBLOCK | IN_CLOEXEC)) {
        if (fd_ < 0 || inotify_add_watch(fd_, file.c_str(), IN_OPEN | IN_ACCESS | IN_CLOSE_NOWRITE) < 0) {
            throw std::runtime_error("cannot watch " + file.string());
        }
    }
    ~FileReads() { close(fd_); }
    FileReads(const FileReads&) = delete;
    FileReads& operator=(const FileReads&) = delete;

    // The opens that read the file, closed since the last call or since this was made. Reads in
    // a row are one event (inotify merges identical events not yet taken), an open and its
    // close are not: each closed open that read something counts once.
    int count() {
        int reads = 0;
        alignas(inotify_event) char buffer[4096];
        for (ssize_t got = ::read(fd_, buffer, sizeof buffer); got > 0; got = ::read(fd_, buffer, sizeof buffer)) {
            for (const char* at = buffer; at < buffer + got;) {
                const auto* event = reinterpret_cast<const inotify_event*>(at);
                if (event->mask & IN_OPEN) {
                    read_ = false;
                } else if (event->mask & IN_ACCESS) {
                    read_ = true;
                } else if (event->mask & IN_CLOSE_NOWRITE) {
                    reads += read_ ? 1 : 0;
                    read_ = false;
                }
                at += sizeof(inotify_event) + event->len;
            }
        }
        return reads;
    }

private:
    int fd_;
    bool read_ = false;   // since the last open
};

}  // namespace patina::test
