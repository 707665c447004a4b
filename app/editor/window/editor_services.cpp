#include "window/editor_services.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>

#include "assets/prepare_scene.h"
#include "gl/gpu_prefilter.h"
#include "picture/compositing.h"
#include "picture/display_image.h"
#include "picture/png_text.h"
#include "io/scene_file.h"
#include "files/file_bytes.h"
#include "views/preview_scene.h"
#include "storage/save_errors.h"
#include "views/screenshot_comparison.h"
#include "storage/shown_path.h"

namespace patina::editor {

namespace {
// "patina-<material>-YYYYmmdd-HHMMSS.png" in `folder`, the name reduced to file-safe
// characters; "-2", "-3", ... when that second already has a screenshot.
std::filesystem::path screenshotPath(const std::filesystem::path& folder, const std::string& material) {
    std::string safe;
    for (char c : material) {
        safe += std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' ? c : '_';
    }
    const std::time_t now = std::time(nullptr);
    char stamp[32];
    std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", std::localtime(&now));
    const std::string stem = "patina-" + (safe.empty() ? "material" : safe) + "-" + stamp;
    std::filesystem::path path = folder / (stem + ".png");
    for (int n = 2; std::filesystem::exists(path); ++n) {
        path = folder / (stem + "-" + std::to_string(n) + ".png");
    }
    return path;
}
}  // namespace

EditorServices::EditorServices(std::shared_ptr<AssetCache> assets)
    : assets_(std::move(assets)), renderer_(std::make_unique<Renderer>()) {}

unsigned EditorServices::viewportTexture(const PreparedScene& scene, const PictureRequest& request, Shown shown) {
    ViewImage& image = view(shown);
    ViewKey key{renderInputs(scene), request};
    // The picture is the same whatever options a channel would be shown with.
    if (request.channel.channel < 0) {
        key.request.channel = {};
    }
    if (image.drawn != key) {
        RenderSettings settings;
        settings.width = request.width;
        settings.height = request.height;
        settings.path = request.path;
        settings.samples = request.samples;
        settings.environment = request.environment;
        settings.channel = key.request.channel;
        settings.readHdr = false;   // the viewport shows and saves the display image only
        const auto start = std::chrono::steady_clock::now();
        image.drawn.reset();   // until the draw succeeds
        renderer_->draw(scene, settings, image.target);
        lastRenderMilliseconds_ =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        image.pbrTally.reset();
        if (request.channel.channel == shader::CHANNEL_PBR_VALIDATION) {
            image.pbrTally = tallyPbrChannel(renderer_->readBack(image.target, false).ldr);
        }
        image.drawn = std::move(key);
    }
    lastGpuMilliseconds_ = renderer_->lastGpuMilliseconds();
    return image.target.displayTexture();
}

namespace {
// The overlay's pixels: a flagged pixel in its verdict's colour, on diagonal stripes of two
// strengths so the picture shows through and the flag reads on any colour; the rest clear.
LdrImage stripedFlags(const LdrImage& shown) {
    LdrImage overlay{shown.width, shown.height, std::vector<uint8_t>(shown.rgba.size(), 0)};
    for (int y = 0; y < shown.height; ++y) {
        for (int x = 0; x < shown.width; ++x) {
            const size_t i = (size_t(y) * size_t(shown.width) + size_t(x)) * 4;
            if (pbrVerdictOfShown(&shown.rgba[i]) != PbrVerdict::Ok) {
                std::copy_n(&shown.rgba[i], 3, &overlay.rgba[i]);
                overlay.rgba[i + 3] = (x + y) / 4 % 2 == 0 ? 230 : 110;
            }
        }
    }
    return overlay;
}
}  // namespace

const EditorServices::PbrOverlay& EditorServices::pbrOverlay(const PreparedScene& scene,
                                                             const PictureRequest& request, Shown shown) {
    OverlayImage& image = overlays_[shown == Shown::A ? 1 : 0];
    const ChannelRequest channel{shader::CHANNEL_PBR_VALIDATION, "", false, request.channel.strictPbr};
    // A channel is drawn by the single path at one sample a pixel (RenderSettings::channel).
    ViewKey key{renderInputs(scene),
                {request.width, request.height, RenderPath::Single, 1, request.environment, channel}};
    if (image.channel.drawn != key) {
        RenderSettings settings;
        settings.width = request.width;
        settings.height = request.height;
        settings.channel = channel;
        settings.readHdr = false;
        image.channel.drawn.reset();   // until the draw succeeds
        renderer_->draw(scene, settings, image.channel.target);
        const LdrImage flags = renderer_->readBack(image.channel.target, false).ldr;
        image.overlay = {std::make_unique<Texture>(stripedFlags(flags)), tallyPbrChannel(flags)};
        image.channel.drawn = std::move(key);
    }
    return image.overlay;
}

const PixelStory* EditorServices::pixelStory(const PreparedScene& scene, int width, int height, int x, int y) {
    if (x < 0 || y < 0 || x >= width || y >= height) {
        return nullptr;
    }
    ReadOut::Key key{renderInputs(scene), width, height};
    if (readOut_.key != key) {
        readOut_ = {};
        readOut_.surfaces = rasterizeSurfaces(scene, width, height);
        readOut_.key = std::move(key);
    }
    if (readOut_.x != x || readOut_.y != y) {
        readOut_.story = patina::pixelStory(scene, *readOut_.surfaces, x, y);
        readOut_.x = x;
        readOut_.y = y;
    }
    return readOut_.story ? &*readOut_.story : nullptr;
}

RenderOutput EditorServices::renderImage(const PreparedScene& scene, int width, int height, RenderPath passes,
                                         const EnvironmentShading& environment, const ChannelRequest& channel) {
    RenderSettings settings;
    settings.width = width;
    settings.height = height;
    settings.path = passes;
    settings.environment = environment;
    settings.channel = channel;
    settings.readHdr = false;   // thumbnails, screenshots and comparisons use the display image
    settings.maxTargetBytes = kOneOffTargetBytes;   // any size `patina render` takes
    return renderer_->render(scene, settings);   // into the renderer's own target, not a view's
}

const EditorServices::Preset* EditorServices::preset(const std::filesystem::path& material) {
    std::error_code error;
    const auto modified = std::filesystem::last_write_time(material, error);
    if (error) {
        return nullptr;
    }
    PresetEntry& entry = presets_[material];
    if (!entry.preset || entry.modified != modified) {
        entry.preset.reset();
        entry.modified = modified;
        try {
            std::vector<std::string> warnings;
            const Material loaded = loadMaterialFile(material, warnings);
            const Scene preview = previewScene(loaded);
            const PreparedScene prepared = prepareScene(preview, *assets_, warnings, prefilterCubeOnGpu);   // its built-in studio, once
            entry.preset = Preset{std::make_unique<Texture>(renderImage(prepared, 64, 64, RenderPath::Single, EnvironmentShading{}).ldr),
                                  loaded.name};
        } catch (const std::exception&) {
            // the browser shows the file without a picture
        }
    }
    return entry.preset ? &*entry.preset : nullptr;
}

const AccuracyNumbers& EditorServices::accuracy(const Material& material) {
    if (!accuracy_ || accuracy_->first != material) {
        accuracy_ = std::pair{material, accuracyOf(material)};
    }
    return accuracy_->second;
}

const std::vector<AlbedoPoint>& EditorServices::albedo(const MaterialParameters& material) {
    for (auto it = albedoCurves_.begin(); it != albedoCurves_.end(); ++it) {
        if (it->first == material) {
            albedoCurves_.splice(albedoCurves_.begin(), albedoCurves_, it);
            return albedoCurves_.front().second;
        }
    }
    albedoCurves_.emplace_front(material, albedoCurve(material, 19, 256));
    if (albedoCurves_.size() > 4) {
        albedoCurves_.pop_back();
    }
    return albedoCurves_.front().second;
}

const Texture* EditorServices::benchChart(const std::filesystem::path& png) {
    std::error_code error;
    const auto modified = std::filesystem::last_write_time(png, error);
    if (error) {
        return nullptr;
    }
    if (!benchChart_.texture || benchChart_.modified != modified) {
        try {
            benchChart_.texture = std::make_unique<Texture>(decodePng(readFileBytes(png)));
        } catch (const std::exception&) {
            benchChart_.texture.reset();
        }
        benchChart_.modified = modified;
    }
    return benchChart_.texture.get();
}

const Texture* EditorServices::mapThumbnail(const std::shared_ptr<const Model>& model, int image) {
    if (!model || image < 0 || size_t(image) >= model->images.size() || model->images[size_t(image)].rgba.empty()) {
        return nullptr;
    }
    if (thumbnailModel_ != model) {
        thumbnailModel_ = model;
        mapThumbnails_.clear();
    }
    std::unique_ptr<Texture>& texture = mapThumbnails_[image];
    if (!texture) {
        const ModelImage& source = model->images[size_t(image)];
        texture = std::make_unique<Texture>(shrunkToFit(source.width, source.height, source.rgba, 160));
    }
    return texture.get();
}

const Texture* EditorServices::environmentThumbnail(const std::shared_ptr<const Environment>& environment) {
    if (!environment) {
        return nullptr;
    }
    if (environmentThumbnail_.first != environment) {
        environmentThumbnail_ = {environment, std::make_unique<Texture>(equirectPreview(environment->image, 256, 128))};
    }
    return environmentThumbnail_.second.get();
}

// One side as the viewport shows it: the picture or the channel shown (View > Channel), with the
// PBR overlay's stripes over it where that is on (as the viewport draws them).
LdrImage EditorServices::sideImage(const Document& document, const Interaction& interaction, const Material* a,
                                   int width, int height) {
    const Scene scene = a ? withMaterial(document, interaction, *a) : renderedScene(document, interaction);
    const PreparedScene prepared = sceneToDraw(document, scene);
    LdrImage shown = renderImage(prepared, width, height, interaction.renderPath, interaction.environmentShading,
                                 interaction.channel)
                         .ldr;
    if (interaction.pbrOverlay) {
        const ChannelRequest flags{shader::CHANNEL_PBR_VALIDATION, "", false, interaction.channel.strictPbr};
        const LdrImage stripes = stripedFlags(
            renderImage(prepared, width, height, RenderPath::Single, interaction.environmentShading, flags).ldr);
        for (size_t i = 0; i + 3 < shown.rgba.size() && i + 3 < stripes.rgba.size(); i += 4) {
            const int alpha = stripes.rgba[i + 3];   // "over": the stripe's colour by its alpha
            for (size_t c = 0; c < 3; ++c) {
                shown.rgba[i + c] = uint8_t((stripes.rgba[i + c] * alpha + shown.rgba[i + c] * (255 - alpha) + 127) / 255);
            }
        }
    }
    return shown;
}

LdrImage EditorServices::comparisonImage(const Document& document, const Interaction& interaction, int halfWidth,
                                         int height) {
    const LdrImage a = sideImage(document, interaction, &*interaction.compareA, halfWidth, height);
    const LdrImage b = sideImage(document, interaction, nullptr, halfWidth, height);
    // Captioned "A: name  r ..." and "B: ...", as the viewport labels them.
    auto caption = [&](char side, Material material) {
        material.name = comparisonLabel(side, material);
        return materialCaption(material, halfWidth);
    };
    return sideBySide(a, b, caption('A', *interaction.compareA), caption('B', labelledMaterial(document, interaction)));
}

LdrImage EditorServices::shownImage(const Document& document, const Interaction& interaction, int width, int height) {
    if (!interaction.compareA || interaction.compareView == CompareView::Single) {
        return sideImage(document, interaction, nullptr, width, height);
    }
    if (interaction.compareView == CompareView::SideBySide) {
        return comparisonImage(document, interaction, std::max(width / 2, 1), height);
    }
    // Split: A's columns left of the divider over B's, the divider and the labels as drawn.
    const LdrImage a = sideImage(document, interaction, &*interaction.compareA, width, height);
    LdrImage shown = sideImage(document, interaction, nullptr, width, height);
    const int split =
        std::clamp(int(std::lround(std::clamp(interaction.splitPosition, 0.0f, 1.0f) * float(width))), 0, width);
    for (int y = 0; y < height; ++y) {
        const size_t row = size_t(y) * size_t(width) * 4;
        std::copy_n(a.rgba.begin() + std::ptrdiff_t(row), size_t(split) * 4, shown.rgba.begin() + std::ptrdiff_t(row));
        for (int x = std::max(split - 1, 0); x < std::min(split + 1, width); ++x) {
            std::fill_n(shown.rgba.begin() + std::ptrdiff_t(row + size_t(x) * 4), 3, uint8_t(255));
        }
    }
    // Each side's label cut to fit its own part (its letter at least).
    const int scale = captionScale(width);
    const int least = textWidth("A...", scale);
    const std::string labelA = fitText(comparisonLabel('A', *interaction.compareA), std::max(split - 16, least), scale);
    const std::string labelB = fitText(comparisonLabel('B', labelledMaterial(document, interaction)),
                                       std::max(width - split - 16, least), scale);
    drawText(shown, 8, 24, labelA, scale, kCaptionColour);
    drawText(shown, width - 8 - textWidth(labelB, scale), 24, labelB, scale, kCaptionColour);
    return shown;
}

std::optional<std::filesystem::path> EditorServices::screenshot(const Document& document,
                                                                const Interaction& interaction,
                                                                const Preferences& preferences, Prompts& prompts,
                                                                int width, int height) {
    std::filesystem::path path = preferences.screenshotFolder / "patina-screenshot.png";   // until named
    try {
        const LdrImage image = shownImage(document, interaction, width, height);
        std::filesystem::create_directories(preferences.screenshotFolder);   // a folder set but not made yet
        path = std::filesystem::absolute(
                   screenshotPath(preferences.screenshotFolder, editedMaterial(document, interaction).name))
                   .lexically_normal();
        std::vector<std::pair<std::string, std::string>> text{{kSceneTextKeyword, sceneToJson(document.scene).dump()}};
        if (const std::string comparison = comparisonText(interaction); !comparison.empty()) {
            text.emplace_back(kComparisonTextKeyword, comparison);   // reopens as the comparison shown
        }
        writeFileAtomic(path, encodePngWithText(image, text));
        prompts.status = "Screenshot saved: " + shownPath(path);
        prompts.lastScreenshot = path;
        return path;
    } catch (const std::exception& error) {
        prompts.error = couldNotSave(path, error);
        return std::nullopt;
    }
}

std::optional<std::filesystem::path> EditorServices::exportComparison(const Document& document,
                                                                      const Interaction& interaction, Prompts& prompts,
                                                                      const std::filesystem::path& path) {
    if (!interaction.compareA) {
        prompts.error = "Set A first: the comparison needs an A material.";
        return std::nullopt;
    }
    try {
        const int width = std::max(viewportWidth / 2, 64), height = std::max(viewportHeight, 64);
        writeFileAtomic(path, encodePng(comparisonImage(document, interaction, width, height)));
        prompts.status = "Exported " + shownPath(path);
        return path;
    } catch (const std::exception& error) {
        prompts.error = couldNotSave(path, error);
        return std::nullopt;
    }
}

}  // namespace patina::editor
