#pragma once
// The shadow maps' resolution and bias (docs/LIGHTING.md section 6): a draw's option
// (RenderSettings::shadowMaps) whose defaults are what every render uses; the shadow
// measurement (accuracy/shadow_accuracy.h) varies them. No GL here: renderer.h's users need none.

namespace patina {

inline constexpr int kShadowMapSize = 2048;

struct ShadowMapSettings {
    int size = kShadowMapSize;   // texels a side of every map, 1 to the GL's largest texture
    // Scales the three biases together: the map's glPolygonOffset (slope 2, constant 4) and the
    // lookup's normal offset (a texel's world size times 1 + 2 sin theta). 1: today's; 0: none
    // (acne); large: the shadow leaves its caster (peter-panning). At least 0.
    float biasScale = 1.0f;

    bool operator==(const ShadowMapSettings&) const = default;
};

}  // namespace patina
