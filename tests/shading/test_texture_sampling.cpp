// The CPU twin of texture sampling (engine/shading/texture_sampling.h) and the textured
// material of shaders/shared/texture.glsl compiled as C++, against values worked by hand from
// glTF 2.0, KHR_texture_transform and GL's texel conventions.
#include <cmath>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "shading/shading.h"
#include "shading/texture_sampling.h"

namespace patina {
namespace {

constexpr float kPi = 3.14159265358979f;

// A data (non-sRGB) texture whose byte i is 4 i + 1: every channel of every texel differs (up to
// 64 channels, 4 x 4 texels).
std::vector<uint8_t> countingBytes(int width, int height) {
    std::vector<uint8_t> bytes(size_t(width) * size_t(height) * 4);
    for (size_t i = 0; i < bytes.size(); ++i) {
        bytes[i] = uint8_t(4 * i + 1);
    }
    return bytes;
}

glm::vec4 texelOf(const std::vector<uint8_t>& bytes, int width, int x, int y) {
    const size_t i = 4 * (size_t(y) * size_t(width) + size_t(x));
    return glm::vec4(bytes[i], bytes[i + 1], bytes[i + 2], bytes[i + 3]) / 255.0f;
}

void expectNear(glm::vec4 got, glm::vec4 want, float tolerance, const char* what) {
    for (int c = 0; c < 4; ++c) {
        EXPECT_NEAR(got[c], want[c], tolerance) << what << ", channel " << c;
    }
}

void expectNear(glm::vec3 got, glm::vec3 want, float tolerance, const char* what) {
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(got[c], want[c], tolerance) << what << ", component " << c;
    }
}

TextureSampler sampler(TextureWrap s, TextureWrap t, bool nearest) {
    TextureSampler result;
    result.wrapS = s;
    result.wrapT = t;
    result.nearestMagnification = nearest;
    return result;
}

TEST(TextureSampling, TexelCentresReturnTheTexelRowsTopFirst) {
    const int width = 4, height = 2;   // not square: u and v, width and height are told apart
    const std::vector<uint8_t> bytes = countingBytes(width, height);
    const LinearTexture texture = linearTexture(bytes.data(), width, height, false);
    for (bool nearest : {false, true}) {
        for (int y = 0; y < height; ++y) {
            for (int x = 0; x < width; ++x) {
                const glm::vec2 centre((float(x) + 0.5f) / float(width), (float(y) + 0.5f) / float(height));
                const glm::vec4 got = sampleTexture(texture, sampler(TextureWrap::Repeat, TextureWrap::Repeat, nearest), centre);
                EXPECT_EQ(got, texelOf(bytes, width, x, y)) << "texel " << x << ", " << y << " nearest " << nearest;
            }
        }
    }
}

TEST(TextureSampling, MidpointsAverageTheirNeighbours) {
    const int width = 4, height = 2;
    const std::vector<uint8_t> bytes = countingBytes(width, height);
    const LinearTexture texture = linearTexture(bytes.data(), width, height, false);
    const TextureSampler clamp = sampler(TextureWrap::ClampToEdge, TextureWrap::ClampToEdge, false);
    // Between the centres of texels 1 and 2 of row 1, and at the corner shared by (1..2, 0..1).
    expectNear(sampleTexture(texture, clamp, {0.5f, 0.75f}),
               0.5f * (texelOf(bytes, width, 1, 1) + texelOf(bytes, width, 2, 1)), 1e-6f, "horizontal midpoint");
    expectNear(sampleTexture(texture, clamp, {0.5f, 0.5f}),
               0.25f * (texelOf(bytes, width, 1, 0) + texelOf(bytes, width, 2, 0) + texelOf(bytes, width, 1, 1) +
                        texelOf(bytes, width, 2, 1)),
               1e-6f, "corner");
    // A quarter of the way from texel 0's centre to texel 1's.
    expectNear(sampleTexture(texture, clamp, {0.1875f, 0.25f}),
               0.75f * texelOf(bytes, width, 0, 0) + 0.25f * texelOf(bytes, width, 1, 0), 1e-6f, "a quarter");
}

TEST(TextureWrapTexel, EachModeAgainstHandComputedIndices) {
    const int indices[] = {-9, -5, -4, -1, 0, 3, 4, 5, 7, 8, 11, 12};
    // Size 4. Repeat: i mod 4. Clamp: into [0, 3]. Mirrored: period 8 reading 0 1 2 3 3 2 1 0.
    const int repeat[] = {3, 3, 0, 3, 0, 3, 0, 1, 3, 0, 3, 0};
    const int clamped[] = {0, 0, 0, 0, 0, 3, 3, 3, 3, 3, 3, 3};
    const int mirrored[] = {0, 3, 3, 0, 0, 3, 3, 2, 0, 0, 3, 3};
    for (size_t k = 0; k < std::size(indices); ++k) {
        const int i = indices[k];
        EXPECT_EQ(shader::wrapTexel(i, 4, shader::TEXTURE_WRAP_REPEAT), repeat[k]) << "repeat " << i;
        EXPECT_EQ(shader::wrapTexel(i, 4, shader::TEXTURE_WRAP_CLAMP_TO_EDGE), clamped[k]) << "clamp " << i;
        EXPECT_EQ(shader::wrapTexel(i, 4, shader::TEXTURE_WRAP_MIRRORED_REPEAT), mirrored[k]) << "mirrored " << i;
    }
    for (int mode : {shader::TEXTURE_WRAP_REPEAT, shader::TEXTURE_WRAP_CLAMP_TO_EDGE, shader::TEXTURE_WRAP_MIRRORED_REPEAT}) {
        EXPECT_EQ(shader::wrapTexel(-3, 1, mode), 0) << "a one-texel row, mode " << mode;
        EXPECT_EQ(shader::wrapTexel(2, 1, mode), 0) << "a one-texel row, mode " << mode;
    }
}

// Which texel of a 4 x 1 row each of four u values reads under one wrap mode.
struct WrapCase {
    TextureWrap wrap;
    int texels[4];
};

void expectRowTexels(bool nearest, const float (&us)[4], const WrapCase (&cases)[3]) {
    const std::vector<uint8_t> bytes = countingBytes(4, 1);
    const LinearTexture texture = linearTexture(bytes.data(), 4, 1, false);
    for (const WrapCase& c : cases) {
        const TextureSampler s = sampler(c.wrap, TextureWrap::Repeat, nearest);
        for (size_t k = 0; k < 4; ++k) {
            EXPECT_EQ(sampleTexture(texture, s, {us[k], 0.5f}), texelOf(bytes, 4, c.texels[k], 0))
                << "wrap " << int(c.wrap) << " at u = " << us[k] << ", nearest " << nearest;
        }
    }
}

// NEAREST outside [0, 1]: u width = -1, 5, 11 and -6.4.
TEST(TextureSampling, NearestWrapsOutsideTheUnitSquare) {
    expectRowTexels(true, {-0.25f, 1.25f, 2.75f, -1.6f},
                    {{TextureWrap::Repeat, {3, 1, 3, 1}},
                     {TextureWrap::ClampToEdge, {0, 3, 3, 0}},
                     {TextureWrap::MirroredRepeat, {0, 2, 3, 1}}});
}

// Bilinear at texel centres outside [0, 1] (x = u 4 - 1/2 = -1, -2, 4, 10) and on the seam.
TEST(TextureSampling, BilinearWrapsEachNeighbourAndBlendsAcrossTheRepeatSeam) {
    expectRowTexels(false, {-0.125f, -0.375f, 1.125f, 2.625f},
                    {{TextureWrap::Repeat, {3, 2, 0, 2}},
                     {TextureWrap::ClampToEdge, {0, 0, 3, 3}},
                     {TextureWrap::MirroredRepeat, {0, 1, 3, 2}}});
    const std::vector<uint8_t> bytes = countingBytes(4, 1);
    const LinearTexture texture = linearTexture(bytes.data(), 4, 1, false);
    // u = 0 and u = 1 lie halfway between texel 3's centre and texel 0's across the seam.
    const glm::vec4 seam = 0.5f * (texelOf(bytes, 4, 3, 0) + texelOf(bytes, 4, 0, 0));
    const TextureSampler repeat = sampler(TextureWrap::Repeat, TextureWrap::Repeat, false);
    expectNear(sampleTexture(texture, repeat, {0.0f, 0.5f}), seam, 1e-6f, "repeat at u = 0");
    expectNear(sampleTexture(texture, repeat, {1.0f, 0.5f}), seam, 1e-6f, "repeat at u = 1");
    const TextureSampler clamp = sampler(TextureWrap::ClampToEdge, TextureWrap::Repeat, false);
    EXPECT_EQ(sampleTexture(texture, clamp, {0.0f, 0.5f}), texelOf(bytes, 4, 0, 0));
    const TextureSampler mirror = sampler(TextureWrap::MirroredRepeat, TextureWrap::Repeat, false);
    EXPECT_EQ(sampleTexture(texture, mirror, {1.0f, 0.5f}), texelOf(bytes, 4, 3, 0));
}

TEST(TextureSampling, WrapSActsOnUAndWrapTOnV) {
    const std::vector<uint8_t> bytes = countingBytes(4, 4);
    const LinearTexture texture = linearTexture(bytes.data(), 4, 4, false);
    // (1.25, 1.25) is texel (5, 5): clamp in u reads column 3, mirrored in v reads row 2.
    const TextureSampler s = sampler(TextureWrap::ClampToEdge, TextureWrap::MirroredRepeat, true);
    EXPECT_EQ(sampleTexture(texture, s, {1.25f, 1.25f}), texelOf(bytes, 4, 3, 2));
}

double srgbFormula(double c) {
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

TEST(TextureSrgb, DecodeIsTheExactPiecewiseCurve) {
    EXPECT_EQ(shader::srgbDecode(0.0f), 0.0f);
    EXPECT_EQ(shader::srgbDecode(1.0f), 1.0f);
    EXPECT_FLOAT_EQ(shader::srgbDecode(0.04045f), 0.04045f / 12.92f);
    // Both pieces meet at the boundary (to the curve's published 4 digits).
    EXPECT_NEAR(shader::srgbDecode(0.040451f), 0.04045f / 12.92f, 1e-6f);
    EXPECT_NEAR(shader::srgbDecode(0.5f), srgbFormula(0.5), 1e-6);
}

TEST(TextureSrgb, ImagesDecodeColourButNotAlpha) {
    // 10 / 255 lies below the 0.04045 knee, 11 / 255 above it.
    const std::vector<uint8_t> bytes = {0, 10, 11, 128, 128, 255, 255, 64};
    const LinearTexture srgb = linearTexture(bytes.data(), 2, 1, true);
    EXPECT_EQ(srgb.texels[0].x, 0.0f);
    EXPECT_FLOAT_EQ(srgb.texels[0].y, float(10.0 / 255.0 / 12.92));
    EXPECT_NEAR(srgb.texels[0].z, srgbFormula(11.0 / 255.0), 1e-7);
    EXPECT_FLOAT_EQ(srgb.texels[0].w, 128.0f / 255.0f);   // alpha is linear
    EXPECT_NEAR(srgb.texels[1].x, srgbFormula(128.0 / 255.0), 1e-6);
    EXPECT_EQ(srgb.texels[1].y, 1.0f);
    EXPECT_FLOAT_EQ(srgb.texels[1].w, 64.0f / 255.0f);
    const LinearTexture data = linearTexture(bytes.data(), 2, 1, false);
    EXPECT_FLOAT_EQ(data.texels[1].x, 128.0f / 255.0f);
}

TEST(TextureSrgb, TexelsDecodeBeforeTheyFilter) {
    // Halfway between black and white is linear 0.5, not decode(0.5) = 0.214.
    const std::vector<uint8_t> bytes = {0, 0, 0, 255, 255, 255, 255, 255};
    const LinearTexture texture = linearTexture(bytes.data(), 2, 1, true);
    const glm::vec4 got = sampleTexture(texture, sampler(TextureWrap::ClampToEdge, TextureWrap::ClampToEdge, false),
                                        {0.5f, 0.5f});
    EXPECT_NEAR(got.x, 0.5f, 1e-6f);
}

TEST(TextureTransformUv, QuarterTurnMapsUToMinusV) {
    TextureTransform quarter;
    quarter.rotation = kPi / 2.0f;
    const glm::vec2 u = transformedUv(quarter, {1.0f, 0.0f});
    EXPECT_NEAR(u.x, 0.0f, 1e-6f);
    EXPECT_NEAR(u.y, -1.0f, 1e-6f);
    const glm::vec2 v = transformedUv(quarter, {0.0f, 1.0f});
    EXPECT_NEAR(v.x, 1.0f, 1e-6f);
    EXPECT_NEAR(v.y, 0.0f, 1e-6f);
}

TEST(TextureTransformUv, ScaleThenRotateThenOffset) {
    TextureTransform transform;
    EXPECT_EQ(transformedUv(transform, {0.3f, -1.7f}), glm::vec2(0.3f, -1.7f));   // the default is identity
    transform.scale = {2.0f, 3.0f};
    transform.offset = {0.25f, 0.5f};
    EXPECT_EQ(transformedUv(transform, {1.0f, 1.0f}), glm::vec2(2.25f, 3.5f));
    // (1, 0) scaled to (2, 0), turned to (0, -2), moved by (0.5, 0); rotating first would give -1.
    transform.scale = {2.0f, 1.0f};
    transform.offset = {0.5f, 0.0f};
    transform.rotation = kPi / 2.0f;
    const glm::vec2 got = transformedUv(transform, {1.0f, 0.0f});
    EXPECT_NEAR(got.x, 0.5f, 1e-6f);
    EXPECT_NEAR(got.y, -2.0f, 1e-6f);
}

// A tangent frame that is not the axes: N, T (w = +1) and B = cross(N, T).
struct Frame {
    glm::vec3 N = glm::normalize(glm::vec3(0.3f, 0.8f, 0.5f));
    glm::vec3 T = glm::normalize(glm::cross(glm::vec3(0.0f, 0.0f, 1.0f), N));
    glm::vec3 B = glm::cross(N, T);
};

TEST(TextureNormalMap, FlatTexelGivesTheGeometricNormal) {
    const Frame f;
    // Exactly (0.5, 0.5, 1): the geometric normal to float precision.
    const glm::vec3 exact = shader::perturbedNormal(f.N, glm::vec4(f.T, 1.0f),
                                                    shader::tangentSpaceNormal({0.5f, 0.5f, 1.0f}, 1.0f));
    expectNear(exact, f.N, 1e-6f, "exact flat texel");
    // An 8-bit file stores 128 / 255, which maps to 1 / 255, not 0: off by about 0.0055.
    const uint8_t bytes[] = {128, 128, 255, 255};
    const LinearTexture texture = linearTexture(bytes, 1, 1, false);
    const glm::vec4 c = texture.texels[0];
    const glm::vec3 fromFile =
        shader::perturbedNormal(f.N, glm::vec4(f.T, 1.0f), shader::tangentSpaceNormal({c.x, c.y, c.z}, 1.0f));
    expectNear(fromFile, f.N, 1e-2f, "128 / 255 texel");
    const float e = 1.0f / 255.0f;
    expectNear(fromFile, glm::normalize(e * f.T + e * f.B + f.N), 1e-6f, "128 / 255 texel, worked exactly");
}

TEST(TextureNormalMap, ScaleTiltsXAndYOnly) {
    // (0.75, 0.5, 1) is (0.5, 0, 1); scale 2 makes it (1, 0, 1).
    const float h = std::sqrt(0.5f);
    expectNear(shader::tangentSpaceNormal({0.75f, 0.5f, 1.0f}, 2.0f), {h, 0.0f, h}, 1e-6f, "scale 2");
    expectNear(shader::tangentSpaceNormal({0.75f, 0.5f, 1.0f}, 0.0f), {0.0f, 0.0f, 1.0f}, 1e-6f, "scale 0");
}

TEST(TextureNormalMap, PlusYFollowsTheBitangentAndAMirroredTangentFlipsIt) {
    const Frame f;
    const glm::vec3 tilted = glm::normalize(glm::vec3(0.3f, 0.4f, 0.8f));
    const glm::vec3 right = shader::perturbedNormal(f.N, glm::vec4(f.T, 1.0f), tilted);
    const glm::vec3 mirrored = shader::perturbedNormal(f.N, glm::vec4(f.T, -1.0f), tilted);
    expectNear(right, tilted.x * f.T + tilted.y * f.B + tilted.z * f.N, 1e-6f, "w = +1");
    expectNear(mirrored, tilted.x * f.T - tilted.y * f.B + tilted.z * f.N, 1e-6f, "w = -1");
    EXPECT_NEAR(glm::dot(right, f.B), 0.4f * glm::inversesqrt(0.89f), 1e-6f);
}

TEST(TextureOcclusion, StrengthBlendsFromOneToTheTexel) {
    EXPECT_EQ(shader::occlusionFactor(0.3f, 0.0f), 1.0f);
    EXPECT_FLOAT_EQ(shader::occlusionFactor(0.3f, 1.0f), 0.3f);
    EXPECT_FLOAT_EQ(shader::occlusionFactor(0.3f, 0.5f), 0.65f);
}

TEST(TextureMaterial, FactorsTimesTexelsFromTheRightChannels) {
    const shader::TexturedMaterial m =
        shader::texturedMaterial({0.5f, 0.8f, 1.0f, 0.6f}, {0.4f, 0.5f, 0.25f, 0.5f}, 0.5f, 0.8f,
                                 {0.9f, 0.6f, 0.3f, 1.0f});
    expectNear(m.baseColor, {0.2f, 0.4f, 0.25f}, 1e-7f, "base colour");
    EXPECT_FLOAT_EQ(m.alpha, 0.3f);
    EXPECT_FLOAT_EQ(m.roughness, 0.3f);    // G
    EXPECT_FLOAT_EQ(m.metallic, 0.24f);    // B
}

// OpenGL 4.6 core 8.14.1: lambda = log2 of the larger derivative's length in texels.
TEST(TextureLevelOfDetail, IsLog2OfTheLargerStepInTexels) {
    EXPECT_FLOAT_EQ(shader::textureLevelOfDetail({1.0f / 64.0f, 0.0f}, {0.0f, 1.0f / 256.0f}, {256.0f, 256.0f}), 2.0f);
    EXPECT_FLOAT_EQ(shader::textureLevelOfDetail({0.0f, 0.0f}, {0.0f, 3.0f / 128.0f}, {64.0f, 128.0f}), std::log2(3.0f));
    EXPECT_LT(shader::textureLevelOfDetail({0.0f, 0.0f}, {0.0f, 0.0f}, {64.0f, 64.0f}), -60.0f);   // magnified
}

// Each level half the last down to 1 x 1, each texel the mean of four: an sRGB image's RGB in
// linear light, its alpha (and a data image's every channel) as stored.
TEST(TextureMipLevels, HalveDownToOneTexelAveragingSrgbInLinearLight) {
    // 5 x 2: black and white columns, alpha 0 and 255.
    std::vector<uint8_t> rgba;
    for (int y = 0; y < 2; ++y) {
        for (int x = 0; x < 5; ++x) {
            const uint8_t v = x % 2 ? 255 : 0;
            rgba.insert(rgba.end(), {v, v, v, v});
        }
    }
    const std::vector<ImageLevel> srgb = mipLevels(rgba.data(), 5, 2, true);
    ASSERT_EQ(srgb.size(), 2u);   // 2 x 1, then 1 x 1
    EXPECT_EQ(srgb[0].width, 2);
    EXPECT_EQ(srgb[0].height, 1);
    EXPECT_EQ(srgb[1].width, 1);
    // Half of white in linear light is sRGB 188, not 128; alpha is data: 128 (127.5 rounded).
    EXPECT_EQ(int(srgb[0].rgba[0]), int(std::lround(255.0f * shader::srgbEncode(0.5f))));
    EXPECT_EQ(int(srgb[0].rgba[0]), 188);
    EXPECT_EQ(int(srgb[0].rgba[3]), 128);
    const std::vector<ImageLevel> data = mipLevels(rgba.data(), 5, 2, false);
    EXPECT_EQ(int(data[0].rgba[0]), 128);
    EXPECT_TRUE(mipLevels(rgba.data(), 1, 1, false).empty());
}

// textureLod's choices (OpenGL 4.6 core 8.14-8.15): level 0 magnified at or below c, the two
// levels around lambda blended by its fraction above it, the last level beyond it.
TEST(TextureMipLevels, TheLevelOfDetailPicksAndBlendsTheLevels) {
    std::vector<LinearTexture> levels;
    for (float v : {0.0f, 0.5f, 1.0f}) {
        levels.push_back({1 << (2 - levels.size()), 1 << (2 - levels.size()), {}});
        levels.back().texels.assign(size_t(levels.back().width * levels.back().height), glm::vec4(v));
    }
    TextureSampler sampler;
    const glm::vec2 uv(0.3f, 0.6f);
    EXPECT_EQ(sampleTextureLod(levels, sampler, uv, -3.0f).x, 0.0f);
    EXPECT_FLOAT_EQ(sampleTextureLod(levels, sampler, uv, 0.5f).x, 0.25f);
    EXPECT_FLOAT_EQ(sampleTextureLod(levels, sampler, uv, 1.25f).x, 0.625f);
    EXPECT_EQ(sampleTextureLod(levels, sampler, uv, 9.0f).x, 1.0f);
    sampler.nearestMinification = true;   // NEAREST_MIPMAP_LINEAR with LINEAR magnification: c = 0.5
    EXPECT_EQ(sampleTextureLod(levels, sampler, uv, 0.4f).x, 0.0f);
    EXPECT_FLOAT_EQ(sampleTextureLod(levels, sampler, uv, 0.75f).x, 0.375f);
    sampler.mipmaps = false;
    EXPECT_EQ(sampleTextureLod(levels, sampler, uv, 2.0f).x, 0.0f);
}

}  // namespace
}  // namespace patina
