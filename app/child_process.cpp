#include "child_process.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <fcntl.h>
#include <stdexcept>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace patina::cli {

ChildRun runSelf(const std::vector<std::string>& arguments) {
    std::vector<std::string> argv{"patina"};
    argv.insert(argv.end(), arguments.begin(), arguments.end());
    std::vector<char*> pointers;
    for (std::string& argument : argv) {
        pointers.push_back(argument.data());
    }
    pointers.push_back(nullptr);
    // The child's stderr goes to an unlinked scratch file, read back only if it fails.
    char errorsPath[] = "/tmp/patina-child-XXXXXX";
    const int errors = mkstemp(errorsPath);
    if (errors < 0) {
        throw std::runtime_error("cannot make a scratch file in /tmp");
    }
    unlink(errorsPath);
    const auto start = std::chrono::steady_clock::now();
    const pid_t child = fork();
    if (child < 0) {
        close(errors);
        throw std::runtime_error("cannot start a child process");
    }
    if (child == 0) {
        const int null = open("/dev/null", O_WRONLY);
        dup2(null, STDOUT_FILENO);
        dup2(errors, STDERR_FILENO);
        close(null);
        close(errors);
        execv("/proc/self/exe", pointers.data());
        _exit(127);
    }
    int status = 0;
    rusage usage{};
    while (wait4(child, &status, 0, &usage) < 0) {
        if (errno != EINTR) {
            close(errors);
            throw std::runtime_error("lost the child process");
        }
    }
    ChildRun run;
    run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    run.peakRssMb = double(usage.ru_maxrss) / 1024.0;   // kilobytes on Linux
    std::string tail;
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        char buffer[512];
        const ssize_t length = pread(errors, buffer, sizeof buffer, 0);
        tail.assign(buffer, size_t(std::max<ssize_t>(length, 0)));
    }
    close(errors);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        std::string command = "patina";
        for (const std::string& argument : arguments) {
            command += " " + argument;
        }
        const std::string how = WIFEXITED(status) ? "exited with " + std::to_string(WEXITSTATUS(status))
                                                  : "was killed by signal " + std::to_string(WTERMSIG(status));
        throw std::runtime_error("`" + command + "` " + how + (tail.empty() ? "" : ": " + tail));
    }
    return run;
}

}  // namespace patina::cli
