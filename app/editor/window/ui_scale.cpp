#include "window/ui_scale.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include <imgui.h>

#include "files/file_bytes.h"

namespace patina::editor {

namespace {
float appliedScale = 1.0f;

// A TrueType or OpenType file's first four bytes; stb_truetype trusts what it is given.
bool looksLikeAFont(const std::vector<uint8_t>& bytes) {
    static const char* const tags[] = {"\x00\x01\x00\x00", "true", "OTTO"};
    return bytes.size() > 12 && std::any_of(std::begin(tags), std::end(tags), [&](const char* tag) {
               return std::memcmp(bytes.data(), tag, 4) == 0;
           });
}
}  // namespace

float uiScaleFor(float contentScale, float setting) {
    const float content = contentScale > 0.0f ? contentScale : 1.0f;
    return std::clamp(content * std::clamp(setting, 0.5f, 3.0f), 0.5f, 4.0f);
}

std::string applyUiScale(float scale, const std::filesystem::path& fontFile) {
    ImGuiIO& io = ImGui::GetIO();
    io.Fonts->Clear();
    std::string message;
    ImFont* font = nullptr;
    try {
        const std::vector<uint8_t> bytes = readFileBytes(fontFile);
        if (!looksLikeAFont(bytes)) {
            throw std::runtime_error(fontFile.string() + " is not a TrueType font");
        }
        // ImGui frees the copy with the atlas.
        void* data = IM_ALLOC(bytes.size());
        std::memcpy(data, bytes.data(), bytes.size());
        ImFontConfig config;
        std::snprintf(config.Name, sizeof config.Name, "%s", fontFile.filename().string().c_str());
        font = io.Fonts->AddFontFromMemoryTTF(data, int(bytes.size()), std::round(kUiFontPixels * scale), &config);
    } catch (const std::exception& error) {
        message = "The UI font could not be read (" + std::string(error.what()) +
                  "): the built-in font is used. Debian's fonts-dejavu-core has it.";
    }
    if (!font) {
        ImFontConfig config;
        config.SizePixels = std::round(13.0f * scale);   // the built-in font's own size, scaled
        io.Fonts->AddFontDefault(&config);
    }
    io.Fonts->Build();
    ImGuiStyle style;
    ImGui::StyleColorsDark(&style);
    style.ScaleAllSizes(scale);
    ImGui::GetStyle() = style;
    appliedScale = scale;
    return message;
}

float uiScale() {
    return appliedScale;
}

}  // namespace patina::editor
