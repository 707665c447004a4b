#pragma once
// tests/data/layers/layers.glb (made by its make_layers.py with Blender 3.4's own glTF
// exporter): a 4 x 2 grid of unit spheres, one Principled BSDF material each, in this order.
#include <filesystem>
#include <string>

namespace patina::test {

enum BlenderLayer { kPlain, kClearcoat, kSheen, kSpecular, kTransmission, kRoughTransmission, kIor, kVolume };

inline constexpr const char* kBlenderLayerNames[] = {"plain",        "clearcoat",          "sheen", "specular",
                                                     "transmission", "rough transmission", "ior",   "volume"};

inline std::filesystem::path blenderLayersFile() {
    return std::filesystem::path(PATINA_SOURCE_DIR) / "tests/data/layers/layers.glb";
}

}  // namespace patina::test
