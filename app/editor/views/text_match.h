#pragma once
#include <string>

namespace patina::editor {

// `text` in lower case (ASCII): file extensions and typed names compared in any case.
std::string lowered(std::string text);
// Whether `text` contains `part`, in any case: how the path dialog's list and the preset
// browser's search box match what is typed.
bool containsAnyCase(const std::string& text, const std::string& part);
// `text` without the spaces and tabs at either end: a name typed in a field.
std::string trimmed(const std::string& text);

}  // namespace patina::editor
