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
    std::string stdoutText;
};

// stderr and stdout go through files in `scratch`.
inline CliRun runPatina(const std::string& arguments, const std::filesystem::path& scratch) {
    const std::filesystem::path errors = scratch / "stderr.txt", output = scratch / "stdout.txt";
    const std::string command =
        std::string(PATINA_EXECUTABLE) + " " + arguments + " 2> " + errors.string() + " > " + output.string();
    const int status = std::system(command.c_str());
    auto contents = [](const std::filesystem::path& path) {
        std::ifstream file(path);
        std::stringstream text;
        text << file.rdbuf();
        return text.str();
    };
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, contents(errors), contents(output)};
}

}  // namespace patina::test
