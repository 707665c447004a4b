// The display transform of shaders/shared/display.glsl, compiled as C++: Khronos PBR Neutral
// against values worked through its published steps by hand (in double precision).
#include <gtest/gtest.h>

#include "common/luminance.h"
#include "shading/shading.h"

namespace patina {
namespace {

void expectNear(glm::vec3 got, glm::vec3 want, const char* what) {
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(got[c], want[c], 2e-6f) << what << ", channel " << c;
    }
}

TEST(PbrNeutral, MatchesThePublishedStepsByHand) {
    using shader::tonemapPbrNeutral;
    // Below the start of compression (0.76 after the offset): the colour less the 0.04 offset.
    expectNear(tonemapPbrNeutral({0.5f, 0.3f, 0.2f}), {0.46f, 0.26f, 0.16f}, "a base colour");
    expectNear(tonemapPbrNeutral({0.8f, 0.8f, 0.8f}), {0.76f, 0.76f, 0.76f}, "0.8 grey");
    // Near black the offset is x - 6.25 x^2: 0.05 - 0.015625.
    expectNear(tonemapPbrNeutral({0.05f, 0.05f, 0.05f}), glm::vec3(0.015625f), "dark grey");
    // Compressed: new peak 1 - 0.24^2 / (0.96 + 0.24 - 0.76) for white.
    expectNear(tonemapPbrNeutral({1.0f, 1.0f, 1.0f}), glm::vec3(0.8690909f), "white");
    // A bright saturated colour: compressed, then desaturated towards the new peak.
    expectNear(tonemapPbrNeutral({4.0f, 2.0f, 1.0f}), {0.9832558f, 0.6399514f, 0.4682992f}, "(4, 2, 1)");
    expectNear(tonemapPbrNeutral({100.0f, 0.0f, 0.0f}), {0.9994210f, 0.9363664f, 0.9363664f}, "bright red");
}

TEST(PbrNeutral, TheDisplayTransformOffersIt) {
    const glm::vec3 linear(4.0f, 2.0f, 1.0f);
    const glm::vec3 shown = shader::displayTransform(linear, 0.0f, shader::TONEMAP_PBR_NEUTRAL);
    const glm::vec3 mapped = shader::tonemapPbrNeutral(linear);
    for (int c = 0; c < 3; ++c) {
        EXPECT_FLOAT_EQ(shown[c], shader::srgbEncode(mapped[c]));
    }
    // Highlights keep some of their hue where clamping goes white: red stays above blue.
    EXPECT_GT(shown.x - shown.z, 0.1f);
}

}  // namespace
// The shaders' Rec. 709 luminance (pbr-validation reads it) is common/luminance.h's.
TEST(Rec709Luminance, TheShadersIsCommons) {
    for (const glm::vec3 colour : {glm::vec3(1.0f, 0.0f, 0.0f), glm::vec3(0.0f, 1.0f, 0.0f), glm::vec3(0.0f, 0.0f, 1.0f),
                                   glm::vec3(0.3f, 0.6f, 0.9f)}) {
        EXPECT_EQ(shader::rec709Luminance(colour), luminance(colour));
    }
}

}  // namespace patina
