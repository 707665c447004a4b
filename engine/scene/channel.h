#pragma once
// The inspector's debug channels by name (docs/INSPECTOR.md): what `render --channel NAME`, the
// editor's View menu and the renderer take. The values are shaders/shared/channels.glsl's.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>

#include "scene/light.h"

namespace patina {

struct ChannelRequest {
    int channel = -1;    // CHANNEL_*; -1: the radiance, no channel
    std::string light;   // CHANNEL_LIGHT's light, by name
    bool srgb = false;   // the display image sRGB-encoded (shownChannel), for colours
    bool strictPbr = false;   // pbr-validation with the strict ranges (PbrRanges::strict)
    bool operator==(const ChannelRequest&) const = default;
};

// CHANNEL_PBR_VALIDATION's ranges as the shaders take them (channels.glsl's pbrVerdict):
// Substance's, or the strict ones.
glm::vec3 channelPbrRanges(const ChannelRequest& request);

// "base-color", ..., "light:NAME", "invalid", "pbr-validation"; nullopt for any other name.
std::optional<ChannelRequest> channelFromName(std::string_view name);
// The request's name, as channelFromName reads it ("" for no channel).
std::string channelName(const ChannelRequest& request);
// Every fixed name, in order ("light:NAME" written so), comma-separated: for messages and help.
std::string channelNameList();
// The fixed names, in order, without light:NAME.
std::vector<std::string> fixedChannelNames();

// Where the channel's lights are in packEnabledLights(lights)' order: the one asked for (-1 none,
// -2 the environment light of that name) and the key light D, G and F are read towards (the
// first enabled light in the scene's order that is not a hemisphere or environment light; -1 none).
struct ChannelLights {
    int asked = -1;
    int key = -1;
};
// Throws InputError naming the lights there are when `request` asks for a light the scene has
// no enabled light of that name for.
ChannelLights channelLights(const std::vector<Light>& lights, const ChannelRequest& request);

}  // namespace patina
