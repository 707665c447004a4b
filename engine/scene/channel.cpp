#include "scene/channel.h"

#include <iterator>

#include "files/input_error.h"
#include "model/pbr_validation.h"
#include "scene/light_packing.h"
#include "shading/shading.h"

namespace patina {

namespace {
// In CHANNEL_* order; CHANNEL_LIGHT's entry is its prefix.
constexpr std::string_view kNames[] = {
    "base-color", "alpha",           "metallic",  "roughness",         "specular",
    "f0",         "diffuse-color",   "occlusion", "emissive",          "uv0",
    "uv1",        "geometry-normal", "shading-normal", "tangent",      "bitangent-sign",
    "nov",        "D",               "G",         "F",                 "diffuse",
    "specular-lighting", "environment-diffuse", "environment-specular", "light:", "invalid",
    "pbr-validation", "clearcoat", "sheen", "transmission"};
static_assert(std::size(kNames) == size_t(shader::CHANNEL_COUNT), "a name for each channel of channels.glsl");
constexpr std::string_view kLightPrefix = "light:";
}  // namespace

glm::vec3 channelPbrRanges(const ChannelRequest& request) {
    return (request.strictPbr ? PbrRanges::strict() : PbrRanges{}).asVector();
}

std::optional<ChannelRequest> channelFromName(std::string_view name) {
    if (name.starts_with(kLightPrefix)) {
        if (name.size() == kLightPrefix.size()) {
            return std::nullopt;
        }
        return ChannelRequest{shader::CHANNEL_LIGHT, std::string(name.substr(kLightPrefix.size()))};
    }
    for (size_t i = 0; i < std::size(kNames); ++i) {
        if (int(i) != shader::CHANNEL_LIGHT && kNames[i] == name) {
            return ChannelRequest{int(i), ""};
        }
    }
    return std::nullopt;
}

std::string channelName(const ChannelRequest& request) {
    if (request.channel < 0 || request.channel >= shader::CHANNEL_COUNT) {
        return "";
    }
    return std::string(kNames[size_t(request.channel)]) + (request.channel == shader::CHANNEL_LIGHT ? request.light : "");
}

std::vector<std::string> fixedChannelNames() {
    std::vector<std::string> names;
    for (size_t i = 0; i < std::size(kNames); ++i) {
        if (int(i) != shader::CHANNEL_LIGHT) {
            names.emplace_back(kNames[i]);
        }
    }
    return names;
}

std::string channelNameList() {
    std::string list;
    for (size_t i = 0; i < std::size(kNames); ++i) {
        list += (list.empty() ? "" : ", ") + std::string(kNames[i]) + (int(i) == shader::CHANNEL_LIGHT ? "NAME" : "");
    }
    return list;
}

ChannelLights channelLights(const std::vector<Light>& lights, const ChannelRequest& request) {
    ChannelLights found;
    const std::vector<size_t> order = enabledLightOrder(lights);
    for (size_t packed = 0; packed < order.size(); ++packed) {
        const Light& light = lights[order[packed]];
        if (light.type != LightType::Hemisphere &&
            (found.key < 0 || order[packed] < order[size_t(found.key)])) {
            found.key = int(packed);
        }
        if (request.channel == shader::CHANNEL_LIGHT && found.asked == -1 && light.name == request.light) {
            found.asked = int(packed);
        }
    }
    if (request.channel != shader::CHANNEL_LIGHT || found.asked >= 0) {
        return found;
    }
    std::string names;
    for (const Light& light : lights) {
        if (light.enabled && light.type == LightType::Environment && light.name == request.light) {
            found.asked = -2;
            return found;
        }
        names += light.enabled ? (names.empty() ? "\"" : ", \"") + light.name + "\"" : "";
    }
    throw InputError("channel light:" + request.light + ": the scene has no enabled light of that name (" +
                     (names.empty() ? std::string("it has no enabled light") : "its enabled lights: " + names) + ")");
}

}  // namespace patina
