// Channel names (scene/channel.h) and the shared channel code's closed forms
// (shaders/shared/channels.glsl).
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "files/input_error.h"
#include "scene/channel.h"
#include "scene/scene.h"
#include "shading/shading.h"

namespace patina {
namespace {

TEST(Channel, EveryNameReadsBackAsItsChannel) {
    const std::vector<std::string> names = fixedChannelNames();
    ASSERT_EQ(names.size(), size_t(shader::CHANNEL_COUNT - 1));   // all but light:NAME
    for (const std::string& name : names) {
        const std::optional<ChannelRequest> request = channelFromName(name);
        ASSERT_TRUE(request) << name;
        EXPECT_EQ(channelName(*request), name);
    }
    EXPECT_EQ(channelFromName("light:warm key")->channel, shader::CHANNEL_LIGHT);
    EXPECT_EQ(channelFromName("light:warm key")->light, "warm key");
    EXPECT_EQ(channelName(*channelFromName("light:warm key")), "light:warm key");
    for (const char* bad : {"", "light:", "Base-Color", "light", "invalid "}) {
        EXPECT_FALSE(channelFromName(bad)) << bad;
    }
}

// The key light is the scene's first enabled light with a direction; a named light is found in
// the packed order (points first), an environment light by -2.
TEST(Channel, TheLightsAreFoundInThePackedOrder) {
    std::vector<Light> lights(4);
    lights[0].type = LightType::Hemisphere;
    lights[0].name = "sky";
    lights[1].type = LightType::Directional;
    lights[1].name = "sun";
    lights[2].type = LightType::Point;
    lights[2].name = "bulb";
    lights[3].type = LightType::Environment;
    lights[3].name = "studio";
    // Packed: bulb (0), sun (1), sky (2).
    EXPECT_EQ(channelLights(lights, *channelFromName("light:sky")).asked, 2);
    EXPECT_EQ(channelLights(lights, *channelFromName("light:sky")).key, 1);   // the sun comes first in the scene
    EXPECT_EQ(channelLights(lights, *channelFromName("light:bulb")).asked, 0);
    EXPECT_EQ(channelLights(lights, *channelFromName("light:studio")).asked, -2);
    lights[1].enabled = false;
    EXPECT_EQ(channelLights(lights, *channelFromName("base-color")).key, 0);
    EXPECT_THROW(channelLights(lights, *channelFromName("light:sun")), InputError);   // disabled
}

TEST(Channel, InvalidMarksNanInfiniteAndNegativeRadianceApart) {
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    EXPECT_EQ(shader::invalidRadiance(glm::vec3(0.5f, 0.0f, 2.0f)), glm::vec3(0.0f));
    EXPECT_EQ(shader::invalidRadiance(glm::vec3(nan, 0.0f, 0.0f)), glm::vec3(1.0f, 0.0f, 0.0f));
    EXPECT_EQ(shader::invalidRadiance(glm::vec3(0.0f, inf, 0.0f)), glm::vec3(0.0f, 1.0f, 0.0f));
    EXPECT_EQ(shader::invalidRadiance(glm::vec3(0.0f, 0.0f, -1e-6f)), glm::vec3(0.0f, 0.0f, 1.0f));
    EXPECT_EQ(shader::invalidRadiance(glm::vec3(nan, -inf, 1.0f)), glm::vec3(1.0f, 1.0f, 1.0f));
}

}  // namespace
}  // namespace patina
