// The display transform of shaders/shared/display.glsl, compiled as C++: Khronos PBR Neutral,
// Hill's ACES fit and AgX against values worked through their published steps in double
// precision (by hand, and for Hill and AgX by a Python script outside the code base, from the
// constants three.js and the Khronos glTF Sample Viewer publish).
#include <cmath>
#include <utility>

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

// The spec's examples (the Khronos viewer's and three.js's ACES at exposure 0): mid grey 0.18
// shows as sRGB 127.2 of 255, 2 as 242.0.
TEST(AcesHill, MidGreyAndTwoShowAsThreeJsShowsThem) {
    const glm::vec3 grey = shader::displayTransform(glm::vec3(0.18f), 0.0f, shader::TONEMAP_ACES_HILL) * 255.0f;
    const glm::vec3 two = shader::displayTransform(glm::vec3(2.0f), 0.0f, shader::TONEMAP_ACES_HILL) * 255.0f;
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(grey[c], 127.2f, 0.05f) << "channel " << c;
        EXPECT_NEAR(two[c], 242.0f, 0.06f) << "channel " << c;
    }
}

TEST(AcesHill, MatchesThePublishedStepsInDoublePrecision) {
    using shader::tonemapAcesHill;
    expectNear(tonemapAcesHill(glm::vec3(0.0f)), glm::vec3(0.0f), "black");
    // M_out's last row sums to 0.99999: a grey's blue comes out a hair below its red and green.
    expectNear(tonemapAcesHill(glm::vec3(1.0f)), {0.7633974f, 0.7633974f, 0.7633898f}, "white");
    expectNear(tonemapAcesHill({0.5f, 0.3f, 0.2f}), {0.5605645f, 0.3804779f, 0.2644471f}, "a base colour");
    expectNear(tonemapAcesHill({4.0f, 2.0f, 1.0f}), {0.9647061f, 0.8922991f, 0.7998549f}, "(4, 2, 1)");
    expectNear(tonemapAcesHill({0.02f, 0.05f, 0.9f}), {0.0190439f, 0.0382440f, 0.7413060f}, "a blue");
    // Clamped: a bright red saturates and turns towards white.
    expectNear(tonemapAcesHill({100.0f, 0.0f, 0.0f}), {1.0f, 0.9802220f, 0.9212882f}, "bright red");
}

// three.js's AgX (Rec. 709 in, Rec. 2020 working space, Rec. 709 out), step by step.
TEST(Agx, MatchesThePublishedStepsInDoublePrecision) {
    using shader::tonemapAgx;
    auto near = [](glm::vec3 got, glm::vec3 want, const char* what) {
        for (int c = 0; c < 3; ++c) {   // the sixth-order fit's terms cancel: float keeps 5 digits
            EXPECT_NEAR(got[c], want[c], 2e-5f) << what << ", channel " << c;
        }
    };
    near(tonemapAgx(glm::vec3(0.0f)), glm::vec3(0.0f), "black");
    near(tonemapAgx(glm::vec3(0.18f)), {0.2145486f, 0.2145024f, 0.2144992f}, "mid grey");
    near(tonemapAgx(glm::vec3(1.0f)), {0.5902294f, 0.5901361f, 0.5901023f}, "white");
    near(tonemapAgx(glm::vec3(2.0f)), {0.7433954f, 0.7432921f, 0.7432391f}, "2");
    near(tonemapAgx({0.5f, 0.3f, 0.2f}), {0.4297258f, 0.3101743f, 0.2428954f}, "a base colour");
    near(tonemapAgx({4.0f, 2.0f, 1.0f}), {0.8833786f, 0.7449356f, 0.6327651f}, "(4, 2, 1)");
    near(tonemapAgx({0.02f, 0.05f, 0.9f}), {0.0604061f, 0.1730686f, 0.6716520f}, "a blue");
    near(tonemapAgx({100.0f, 0.0f, 0.0f}), {1.0f, 0.9800001f, 0.9283749f}, "bright red");
}

// Each tone map is the display transform's for its index, between exposure and sRGB; the
// Narkowicz fit keeps the index "aces" had, so old scenes show as before.
TEST(DisplayTransform, EachToneMapIsOfferedBetweenExposureAndSrgb) {
    const glm::vec3 linear(0.9f, 0.45f, 0.2f);
    const float stops = 1.5f;
    const glm::vec3 exposed = linear * std::exp2(stops);
    const std::pair<int, glm::vec3> cases[] = {
        {shader::TONEMAP_ACES_NARKOWICZ, shader::tonemapAcesNarkowicz(exposed)},
        {shader::TONEMAP_ACES_HILL, shader::tonemapAcesHill(exposed)},
        {shader::TONEMAP_AGX, shader::tonemapAgx(exposed)},
        {shader::TONEMAP_PBR_NEUTRAL, glm::clamp(shader::tonemapPbrNeutral(exposed), 0.0f, 1.0f)}};
    for (const auto& [index, mapped] : cases) {
        const glm::vec3 shown = shader::displayTransform(linear, stops, index);
        for (int c = 0; c < 3; ++c) {
            EXPECT_FLOAT_EQ(shown[c], shader::srgbEncode(mapped[c])) << "tone map " << index << ", channel " << c;
        }
    }
    EXPECT_EQ(shader::TONEMAP_ACES_NARKOWICZ, 1);
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
