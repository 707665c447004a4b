// The inspector's debug channels (docs/INSPECTOR.md): the GPU's channel render (shade.frag with
// PATINA_CHANNEL) against the CPU twin (reference/channel_image.h), which gathers the same
// inputs through the same shared functions; and against what the channels must be by their
// definition (the lobes add up to the rendered radiance, a sphere's normal is its position).
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include <gtest/gtest.h>

#include "bench/render_bench.h"
#include "files/input_error.h"
#include "gl/renderer.h"
#include "picture/display_image.h"
#include "picture/pbr_tally.h"
#include "model/pbr_validation.h"
#include "reference/channel_image.h"
#include "reference/pixel_story.h"
#include "reference/pixel_surfaces.h"
#include "scene/channel.h"
#include "shading/shading.h"
#include "test_support.h"

namespace patina {
namespace {

constexpr int kSize = 96;

// |a - b| within an absolute floor plus a fraction of b, component by component.
bool near(glm::vec3 a, glm::vec3 b, float fraction, float floor) {
    for (int c = 0; c < 3; ++c) {
        if (!(std::abs(a[c] - b[c]) <= floor + fraction * std::abs(b[c]))) {
            return false;
        }
    }
    return true;
}

// Pixels whose whole 3 x 3 neighbourhood the surface covers: away from the silhouette, where
// a pixel centre may fall either side of an edge by rounding.
bool inside(const PixelSurfaces& surfaces, int x, int y) {
    for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
            const int u = x + dx, v = y + dy;
            if (u < 0 || v < 0 || u >= surfaces.width || v >= surfaces.height ||
                surfaces.sampleOfPixel[size_t(v * surfaces.width + u)] < 0) {
                return false;
            }
        }
    }
    return true;
}

class Channels : public ::testing::Test {
protected:
    HdrImage gpu(const PreparedScene& prepared, const ChannelRequest& request, RenderPath path = RenderPath::Single) {
        RenderSettings settings = test::renderSettings(kSize, kSize, path, 4);
        settings.channel = request;
        return renderer_.render(prepared, settings).hdr;
    }

    HeadlessContext& context_ = test::glContext();
    Renderer renderer_;
};

// Every channel of the default scene (the sphere under two point lights, a hemisphere light and
// the studio environment), and each light's own: the GPU's value is the CPU twin's at nearly
// every pixel inside the silhouette. They differ by the environment's cube map filtering
// (the GPU's seamless trilinear lookup against the CPU's) and fp32 rounding.
TEST_F(Channels, EveryChannelOfTheDefaultSceneIsTheCpuTwins) {
    const PreparedScene& prepared = test::preparedDefault();
    const PixelSurfaces surfaces = rasterizeSurfaces(prepared, kSize, kSize);
    std::vector<std::string> names = fixedChannelNames();
    for (const Light& light : prepared.scene.lights) {
        names.push_back("light:" + light.name);
    }
    for (const std::string& name : names) {
        const ChannelRequest request = *channelFromName(name);
        const HdrImage a = gpu(prepared, request), b = channelImage(prepared, surfaces, request);
        int covered = 0, agreeing = 0;
        for (int y = 0; y < kSize; ++y) {
            for (int x = 0; x < kSize; ++x) {
                if (inside(surfaces, x, y)) {
                    ++covered;
                    agreeing += near(test::pixel(a, x, y), test::pixel(b, x, y), 1e-2f, 2e-3f);
                }
            }
        }
        EXPECT_GT(covered, 2000) << name;
        EXPECT_GE(agreeing, covered * 99 / 100) << name << ": " << agreeing << " of " << covered;
    }
}

// Off the surface a channel is 0 (no surface, no data), not the scene's background colour.
TEST_F(Channels, TheBackgroundOfAChannelIsZero) {
    const HdrImage image = gpu(test::preparedDefault(), *channelFromName("base-color"));
    EXPECT_EQ(test::pixel(image, 0, 0), glm::vec3(0.0f));
    EXPECT_EQ(test::pixel(image, kSize / 2, kSize / 2), test::preparedDefault().scene.material.baseColor);
}

// The GPU's display image of a channel is the shared shownChannel of its values, as the CLI's
// PNG is: signed normals around mid-grey, colours sRGB-encoded only when asked.
TEST_F(Channels, TheDisplayImageShowsTheChannelAsTheClisPngDoes) {
    for (const char* name : {"shading-normal", "base-color"}) {
        for (bool srgb : {false, true}) {
            RenderSettings settings = test::renderSettings(kSize, kSize, RenderPath::Specialised, 4);
            settings.channel = *channelFromName(name);
            settings.channel.srgb = srgb;
            const RenderOutput output = renderer_.render(test::preparedDefault(), settings);
            const LdrImage expected = channelDisplayImage(output.hdr, settings.channel.channel, srgb);
            int differing = 0;
            for (size_t i = 0; i < expected.rgba.size(); ++i) {
                differing += std::abs(int(expected.rgba[i]) - int(output.ldr.rgba[i])) > 1;
            }
            EXPECT_EQ(differing, 0) << name << (srgb ? " sRGB" : "");
        }
    }
}

// The lobes add up: diffuse + specular-lighting (every light and the environment, occlusion
// applied) is the radiance the product's own render shows, on every path.
TEST_F(Channels, TheDiffuseAndSpecularChannelsAddUpToTheRender) {
    const PreparedScene& prepared = test::preparedDefault();
    const PixelSurfaces surfaces = rasterizeSurfaces(prepared, kSize, kSize);
    const HdrImage diffuse = gpu(prepared, *channelFromName("diffuse"));
    const HdrImage specular = gpu(prepared, *channelFromName("specular-lighting"));
    for (RenderPath path : {RenderPath::Single, RenderPath::Multi, RenderPath::Specialised}) {
        const HdrImage shown = renderer_.render(prepared, test::renderSettings(kSize, kSize, path, 1)).hdr;
        int covered = 0, agreeing = 0;
        for (int y = 0; y < kSize; ++y) {
            for (int x = 0; x < kSize; ++x) {
                if (inside(surfaces, x, y)) {
                    ++covered;
                    const glm::vec3 sum = test::pixel(diffuse, x, y) + test::pixel(specular, x, y);
                    agreeing += near(sum, test::pixel(shown, x, y), 1e-3f, 1e-5f);
                }
            }
        }
        EXPECT_GE(agreeing, covered * 999 / 1000) << renderPathName(path) << ": " << agreeing << " of " << covered;
    }
}

// A unit sphere at the origin: its geometry and shading normal are its position, and N.V is
// the cosine to the camera (built-in meshes have no maps: the two normals are one).
TEST_F(Channels, ASpheresNormalIsItsPosition) {
    const PreparedScene& prepared = test::preparedDefault();
    ASSERT_EQ(prepared.scene.mesh, MeshKind::Sphere);
    const PixelSurfaces surfaces = rasterizeSurfaces(prepared, kSize, kSize);
    const HdrImage geometry = gpu(prepared, *channelFromName("geometry-normal"));
    const HdrImage shading = gpu(prepared, *channelFromName("shading-normal"));
    const HdrImage nov = gpu(prepared, *channelFromName("nov"));
    int checked = 0;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            if (!inside(surfaces, x, y)) {
                continue;
            }
            const ProbeSample& sample = surfaces.samples[size_t(surfaces.sampleOfPixel[size_t(y * kSize + x)])];
            const glm::vec3 position = glm::normalize(sample.position);
            // The sphere is a mesh: its interpolated normal is the position's within its facets.
            EXPECT_TRUE(near(test::pixel(geometry, x, y), position, 0.0f, 1e-2f)) << x << " " << y;
            EXPECT_EQ(test::pixel(shading, x, y), test::pixel(geometry, x, y)) << x << " " << y;
            const float cosine = std::max(glm::dot(glm::normalize(test::pixel(shading, x, y)), sample.toViewer), 1e-4f);
            EXPECT_NEAR(test::pixel(nov, x, y).x, cosine, 1e-3f) << x << " " << y;
            ++checked;
        }
    }
    EXPECT_GT(checked, 2000);
}

// The per-light channels split the lighting: the lights' own channels add up to the diffuse and
// specular lighting together.
TEST_F(Channels, TheLightsChannelsAddUpToTheLighting) {
    const PreparedScene& prepared = test::preparedDefault();
    const PixelSurfaces surfaces = rasterizeSurfaces(prepared, kSize, kSize);
    HdrImage sum{kSize, kSize, std::vector<float>(size_t(kSize * kSize * 3), 0.0f)};
    for (const Light& light : prepared.scene.lights) {
        const HdrImage own = channelImage(prepared, surfaces, *channelFromName("light:" + light.name));
        for (size_t i = 0; i < sum.rgb.size(); ++i) {
            sum.rgb[i] += light.enabled ? own.rgb[i] : 0.0f;
        }
    }
    const HdrImage diffuse = channelImage(prepared, surfaces, *channelFromName("diffuse"));
    const HdrImage specular = channelImage(prepared, surfaces, *channelFromName("specular-lighting"));
    for (int y = 0; y < kSize; y += 3) {
        for (int x = 0; x < kSize; x += 3) {
            EXPECT_TRUE(near(test::pixel(sum, x, y), test::pixel(diffuse, x, y) + test::pixel(specular, x, y), 1e-5f,
                             1e-6f))
                << x << " " << y;
        }
    }
}

// `invalid` flags what the renderer computed, on the GPU: a light of negative intensity (which a
// script can set) makes negative radiance where it lights, blue; elsewhere the channel is 0.
TEST_F(Channels, InvalidFlagsNegativeRadianceOnTheGpu) {
    Scene scene = defaultScene();
    scene.lights = {scene.lights.front()};   // the warm key alone, no environment
    scene.lights[0].intensity = -5.0f;
    const PreparedScene prepared = test::prepared(scene);
    const HdrImage invalid = gpu(prepared, *channelFromName("invalid"));
    const PixelSurfaces surfaces = rasterizeSurfaces(prepared, kSize, kSize);
    const HdrImage twin = channelImage(prepared, surfaces, *channelFromName("invalid"));
    int flagged = 0, covered = 0, agreeing = 0;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            const glm::vec3 value = test::pixel(invalid, x, y);
            EXPECT_EQ(value.r, 0.0f);
            EXPECT_EQ(value.g, 0.0f);
            flagged += value.b == 1.0f;
            if (inside(surfaces, x, y)) {
                ++covered;
                agreeing += value == test::pixel(twin, x, y);   // rounding may differ at the terminator
            }
        }
    }
    EXPECT_GT(flagged, 500);
    EXPECT_GE(agreeing, covered * 99 / 100);
}

// A channel asked for by a name the scene's lights lack is refused with the names there are.
TEST_F(Channels, AnUnknownLightIsRefusedWithTheLightsThereAre) {
    EXPECT_THROW(
        {
            try {
                gpu(test::preparedDefault(), *channelFromName("light:nobody"));
            } catch (const InputError& error) {
                EXPECT_NE(std::string(error.what()).find("\"warm key\""), std::string::npos) << error.what();
                throw;
            }
        },
        InputError);
}

// pbr-validation flags every pixel of a uniform material exactly as the batch check
// (checkBaseColor, `patina validate`) judges its base colour: each verdict in its colour, the
// accepted ones grey at the lightness read; with sRGB encoding the flags stay exact; the strict
// ranges flag what the default ones let pass. A transmitting part's bright end is its reflected
// share's: a clear glass's white base is accepted (it was flagged brighter than snow).
TEST_F(Channels, PbrValidationFlagsEveryPixelAsTheBatchCheckJudgesTheMaterial) {
    struct Case {
        glm::vec3 baseColor;
        float metallic;
        bool strict;
        float transmission = 0.0f;
    };
    const Case cases[] = {
        {glm::vec3(0.004f), 0.0f, false},                 // darker than charcoal
        {glm::vec3(0.95f, 0.9f, 0.9f), 0.0f, false},      // brighter than snow
        {glm::vec3(0.2f, 0.15f, 0.1f), 1.0f, false},      // a metal too dark
        {glm::vec3(0.9f, 0.6f, 0.3f), 1.0f, false},       // copper-like: accepted
        {glm::vec3(0.025f), 0.0f, false},                 // lightness 44: accepted
        {glm::vec3(0.025f), 0.0f, true},                  // ... below the strict 50
        {glm::vec3(1.0f), 0.0f, false, 1.0f},             // a clear glass: it reflects none of its white
        {glm::vec3(1.0f), 0.0f, false, 0.05f},            // a white that passes 5%: too bright still
        {glm::vec3(0.004f), 0.0f, false, 0.9f},           // a black glass: too dark, whatever passes
    };
    for (const Case& c : cases) {
        Scene scene = test::preparedDefault().scene;
        scene.material.baseColor = c.baseColor;
        scene.material.metallic = c.metallic;
        scene.material.transmission = c.transmission;
        const PreparedScene prepared = test::prepared(scene);
        const PbrCheck check =
            checkBaseColor(c.baseColor, c.metallic, c.transmission, c.strict ? PbrRanges::strict() : PbrRanges{});
        if (c.transmission > 0.0f) {   // the cases say what the check must find
            EXPECT_EQ(check.verdict, c.transmission == 1.0f       ? PbrVerdict::Ok
                                     : c.baseColor.r == 1.0f       ? PbrVerdict::DielectricTooBright
                                                                   : PbrVerdict::DielectricTooDark);
        }
        ChannelRequest request = *channelFromName("pbr-validation");
        request.strictPbr = c.strict;
        for (bool srgb : {false, true}) {
            request.srgb = srgb;
            RenderSettings settings = test::renderSettings(kSize, kSize, RenderPath::Single, 1);
            settings.channel = request;
            const RenderOutput output = renderer_.render(prepared, settings);
            const PbrTally tally = tallyPbrChannel(output.ldr);
            EXPECT_GT(tally.texels, 2000u);
            const size_t expected = check.verdict == PbrVerdict::Ok ? 0 : tally.texels;
            EXPECT_EQ(tally.flagged(), expected) << c.baseColor.r << " metallic " << c.metallic;
            EXPECT_EQ(tally.dielectricDark, check.verdict == PbrVerdict::DielectricTooDark ? tally.texels : 0u);
            EXPECT_EQ(tally.dielectricBright, check.verdict == PbrVerdict::DielectricTooBright ? tally.texels : 0u);
            EXPECT_EQ(tally.metalDark, check.verdict == PbrVerdict::MetalTooDark ? tally.texels : 0u);
            if (check.verdict == PbrVerdict::Ok && !srgb) {
                // The grey's byte is the lightness the check read.
                const uint8_t* centre = &output.ldr.rgba[(size_t(kSize / 2) * kSize + kSize / 2) * 4];
                EXPECT_EQ(int(centre[0]), check.value);
                EXPECT_EQ(int(centre[1]), check.value);
            }
        }
    }
}

// The default scene (its lights and environment) with the `gltf` model and a layer: the
// bench's car paint coat, velvet sheen or clear glass (docs/SHADING.md S5, S6, S7), the glass
// rough and tinted green over a thickness (KHR_materials_volume's T in the channel too).
Scene layeredScene(const std::string& layer) {
    const bool glass = layer == "transmission" || layer == "sheened glass" || layer == "filmed glass";
    Scene scene = withBenchLayer(defaultScene(), glass ? "transmission" : layer);
    if (layer == "sheened glass") {   // the velvet's sheen over the glass: the sheen weighs what passes
        scene.material.sheenColor = withBenchLayer(scene, "sheen").material.sheenColor;
        scene.material.sheenRoughness = withBenchLayer(scene, "sheen").material.sheenRoughness;
    }
    if (layer == "filmed glass") {   // the bench's film over the glass: what it reflects does not pass
        const Material film = withBenchLayer(scene, "iridescence").material;
        scene.material.iridescence = film.iridescence;
        scene.material.iridescenceIor = film.iridescenceIor;
        scene.material.iridescenceThicknessMinimum = film.iridescenceThicknessMinimum;
        scene.material.iridescenceThicknessMaximum = film.iridescenceThicknessMaximum;
    }
    if (glass) {
        scene.material.roughness = 0.2f;
        scene.material.thickness = 0.5f;
        scene.material.attenuationColor = {0.6f, 0.9f, 0.7f};
        scene.material.attenuationDistance = 1.0f;
    }
    return scene;
}

// The layers' channels (issue 36): a coated part's clearcoat channel, a sheened part's sheen
// channel and a transmitting part's transmission channel are the coat's, the sheen's and the
// wall's own light, the GPU's the CPU twin's, bright where the layer shows (the coat's
// highlight, the sheen's rim, the environment through the glass); the same channel of the bare
// part, and another layer's channel of each, is 0 everywhere, on the GPU and the CPU.
TEST_F(Channels, TheLayersChannelsAreTheirOwnLightAndZeroWithoutTheLayer) {
    for (const std::string layer : {"clearcoat", "sheen", "transmission"}) {
        const Scene layered = layeredScene(layer), bare = layeredScene("");
        const PreparedScene layeredPrepared{layered, test::preparedDefault().mesh, test::preparedDefault().environment};
        const PreparedScene barePrepared{bare, test::preparedDefault().mesh, test::preparedDefault().environment};
        const PixelSurfaces surfaces = rasterizeSurfaces(layeredPrepared, kSize, kSize);
        const ChannelRequest request = *channelFromName(layer);
        const ChannelRequest other = *channelFromName(layer == "clearcoat" ? "sheen" : "clearcoat");
        const HdrImage a = gpu(layeredPrepared, request), b = channelImage(layeredPrepared, surfaces, request);
        int covered = 0, agreeing = 0;
        float brightest = 0.0f;
        for (int y = 0; y < kSize; ++y) {
            for (int x = 0; x < kSize; ++x) {
                if (inside(surfaces, x, y)) {
                    ++covered;
                    agreeing += near(test::pixel(a, x, y), test::pixel(b, x, y), 1e-2f, 2e-3f);
                    const glm::vec3 v = test::pixel(b, x, y);
                    brightest = std::max({brightest, v.x, v.y, v.z});
                }
            }
        }
        EXPECT_GT(covered, 2000) << layer;
        EXPECT_GE(agreeing, covered * 99 / 100) << layer << ": " << agreeing << " of " << covered;
        EXPECT_GT(brightest, 0.05f) << layer;
        const char* const kZeros[] = {"the bare part's on the GPU", "the bare part's on the CPU",
                                      "the other layer's on the GPU", "the other layer's on the CPU"};
        const PixelSurfaces bareSurfaces = rasterizeSurfaces(barePrepared, kSize, kSize);   // they hold the materials
        const HdrImage zeros[] = {gpu(barePrepared, request), channelImage(barePrepared, bareSurfaces, request),
                                  gpu(layeredPrepared, other), channelImage(layeredPrepared, surfaces, other)};
        for (size_t k = 0; k < std::size(zeros); ++k) {
            EXPECT_EQ(*std::max_element(zeros[k].rgb.begin(), zeros[k].rgb.end()), 0.0f) << layer << ": " << kZeros[k];
        }
    }
}

// With a layer the CPU twin's radiance (what `inspect` and the read-out show) is the render's:
// the base seen through the coat and weighed by the sheen's albedo scaling, the layer's own
// light added; without the layers in the sum a coat's highlight, a sheen's rim or what shows
// through a glass (and the diffuse it takes away) would be missing; under a sheen the glass's
// light is weighed by the sheen's albedo scaling on both; an anisotropic part's lobe is stretched
// on both (KHR_materials_anisotropy's, turned from the fallback direction), and a film over a
// glass takes what it reflects from what passes on both. Nothing stands behind the sphere, so
// the render's scene behind it adds nothing the twin lacks.
TEST_F(Channels, TheCpuTwinsRadianceWithALayerIsTheRenders) {
    for (const std::string layer : {"clearcoat", "sheen", "transmission", "sheened glass", "anisotropy", "filmed glass"}) {
        const Scene scene = layeredScene(layer);
        const PreparedScene prepared{scene, test::preparedDefault().mesh, test::preparedDefault().environment};
        const PixelSurfaces surfaces = rasterizeSurfaces(prepared, kSize, kSize);
        const HdrImage shown = renderer_.render(prepared, test::renderSettings(kSize, kSize, RenderPath::Single, 1)).hdr;
        int covered = 0, agreeing = 0;
        for (int y = 0; y < kSize; y += 2) {
            for (int x = 0; x < kSize; x += 2) {
                if (inside(surfaces, x, y)) {
                    ++covered;
                    const std::optional<PixelStory> story = pixelStory(prepared, surfaces, x, y);
                    agreeing += story && near(story->inputs.radiance, test::pixel(shown, x, y), 1e-2f, 2e-3f);
                }
            }
        }
        EXPECT_GT(covered, 500) << layer;
        EXPECT_GE(agreeing, covered * 99 / 100) << layer << ": " << agreeing << " of " << covered;
    }
}

// KHR_materials_anisotropy in the inspector (docs/SHADING.md S8): an anisotropic part's D, G,
// specular lighting and environment channels are the CPU twin's on the GPU, and they show the
// stretched lobe, not the round one: D and the specular lighting differ from the same part with
// no strength over much of the sphere (the round lobe's channels were drawn before).
TEST_F(Channels, AnAnisotropicPartsTermsAndLightingAreTheTwinsAndStretched) {
    const Scene brushed = layeredScene("anisotropy");
    Scene round = brushed;
    round.material.anisotropyStrength = 0.0f;
    const PreparedScene prepared{brushed, test::preparedDefault().mesh, test::preparedDefault().environment};
    const PreparedScene roundPrepared{round, test::preparedDefault().mesh, test::preparedDefault().environment};
    const PixelSurfaces surfaces = rasterizeSurfaces(prepared, kSize, kSize);
    const PixelSurfaces roundSurfaces = rasterizeSurfaces(roundPrepared, kSize, kSize);
    for (const std::string name : {"D", "G", "specular-lighting", "environment-specular"}) {
        const ChannelRequest request = *channelFromName(name);
        const HdrImage a = gpu(prepared, request), b = channelImage(prepared, surfaces, request);
        const HdrImage r = channelImage(roundPrepared, roundSurfaces, request);
        int covered = 0, agreeing = 0, stretched = 0;
        for (int y = 0; y < kSize; ++y) {
            for (int x = 0; x < kSize; ++x) {
                if (inside(surfaces, x, y)) {
                    ++covered;
                    agreeing += near(test::pixel(a, x, y), test::pixel(b, x, y), 1e-2f, 2e-3f);
                    stretched += !near(test::pixel(b, x, y), test::pixel(r, x, y), 0.05f, 2e-3f);
                }
            }
        }
        EXPECT_GT(covered, 2000) << name;
        EXPECT_GE(agreeing, covered * 99 / 100) << name << ": " << agreeing << " of " << covered;
        EXPECT_GT(stretched, covered / 4) << name << ": " << stretched << " of " << covered;
    }
}

}  // namespace
}  // namespace patina
