#include "storage/open_folder.h"

#include <chrono>
#include <cstring>
#include <thread>

#include <spawn.h>
#include <sys/wait.h>

extern char** environ;

namespace patina::editor {

std::string showFolder(const std::filesystem::path& folder, const std::string& opener, RunningOpeners& running) {
    std::erase_if(running, [](pid_t child) { return waitpid(child, nullptr, WNOHANG) != 0; });
    std::error_code error;
    std::filesystem::path absolute = std::filesystem::absolute(folder, error).lexically_normal();
    if (!absolute.has_filename()) {
        absolute = absolute.parent_path();   // "/x/" from ".": said as "/x"
    }
    const std::string byHand = "; its path is " + absolute.string();
    if (!std::filesystem::is_directory(absolute, error)) {
        return "Could not open the folder " + absolute.string() + ": it does not exist yet";
    }
    std::string program = opener, argument = absolute.string();
    char* argv[] = {program.data(), argument.data(), nullptr};
    pid_t child = 0;
    if (const int failed = posix_spawnp(&child, program.c_str(), nullptr, nullptr, argv, environ); failed != 0) {
        return "Could not open the folder: " + opener + " " +
               (failed == ENOENT ? "is not installed (Debian's xdg-utils has it)" : std::string(std::strerror(failed))) +
               byHand;
    }
    // xdg-open hands the folder to the file manager and returns; give it a moment to fail.
    const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(2);
    int status = 0;
    while (std::chrono::steady_clock::now() < end) {
        if (waitpid(child, &status, WNOHANG) == child) {
            if (WIFEXITED(status) && WEXITSTATUS(status) == 0) {
                return "";
            }
            return "Could not open the folder: " + opener + " failed (" +
                   (WIFEXITED(status) ? "exit code " + std::to_string(WEXITSTATUS(status)) : std::string("killed")) +
                   ": is a file manager installed?)" + byHand;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    running.push_back(child);
    return "";
}

}  // namespace patina::editor
