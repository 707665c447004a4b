#pragma once
// What Patina draws of each glTF extension a file uses (glTF 2.0 section 3.12: extensionsUsed
// lists them all, extensionsRequired those a client must support to load the file at all).
// Every file is told: each extension it uses becomes a ModelExtension, and one Patina does not
// draw a line in Model::notes (the editor's status line, `render` and `validate` print them).
#include <string>
#include <vector>

#include "model/model.h"

namespace patina::gltf {

// The extension `name` as Patina treats it; `required` as the file says.
ModelExtension modelExtension(const std::string& name, bool required);

// Every extension of extensionsUsed (and any of extensionsRequired that it forgot), in the
// file's order.
std::vector<ModelExtension> modelExtensions(const std::vector<std::string>& used,
                                            const std::vector<std::string>& required);

// "KHR_materials_diffuse_transmission (not drawn): light through the surface is left out; the
// material shows opaque".
std::string extensionLine(const ModelExtension& extension);

// Throws InputError("SOURCE: requires the extension NAME, which Patina does not draw (...)")
// for the first extension of `required` that Patina cannot draw: such a file cannot be shown
// without it (glTF 2.0 section 3.12).
void refuseUndrawnRequired(const std::vector<std::string>& required, const std::string& source);

}  // namespace patina::gltf
