#pragma once
// A failed save (or rename, or delete) in words an artist reads: "Could not save gold.json: the
// folder /x is read-only", not the system call that failed.
#include <exception>
#include <filesystem>
#include <string>

namespace patina::editor {

// "Could not <action> <file's name>: <why>".
std::string couldNot(const std::string& action, const std::filesystem::path& file, const std::exception& error);
std::string couldNotSave(const std::filesystem::path& file, const std::exception& error);

}  // namespace patina::editor
