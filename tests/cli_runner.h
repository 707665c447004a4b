#pragma once
// Runs the built `patina` binary (PATINA_EXECUTABLE) with a shell command line.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <sys/wait.h>

namespace patina::test {

struct CliRun {
    int exitCode;
    std::string stderrText;
};

// stderr goes through a file in `scratch`; stdout is dropped.
inline CliRun runPatina(const std::string& arguments, const std::filesystem::path& scratch) {
    const std::filesystem::path errors = scratch / "stderr.txt";
    const std::string command =
        std::string(PATINA_EXECUTABLE) + " " + arguments + " 2> " + errors.string() + " > /dev/null";
    const int status = std::system(command.c_str());
    std::ifstream file(errors);
    std::stringstream text;
    text << file.rdbuf();
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, text.str()};
}

}  // namespace patina::test
