// PNG text chunks (engine/image/png_text.h): the scene the editor embeds in its PNGs, and a reader
// that refuses damaged or hostile files with InputError instead of reading past the buffer.
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include <zlib.h>

#include "png_crc.h"
#include "scratch_test.h"

#include "image/image.h"
#include "files/input_error.h"
#include "io/json_writer.h"
#include "image/png_chunks.h"
#include "image/png_stream.h"
#include "picture/png_text.h"
#include "io/scene_file.h"
#include "files/file_bytes.h"

namespace patina {
namespace {

namespace fs = std::filesystem;

LdrImage testImage() {
    LdrImage image{5, 3, std::vector<uint8_t>(5 * 3 * 4)};
    for (size_t i = 0; i < image.rgba.size(); ++i) {
        image.rgba[i] = i % 4 == 3 ? 255 : uint8_t(i * 37);
    }
    return image;
}

uint32_t referenceCrc(const std::string& bytes) {
    return test::pngCrc(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
}

std::string bigEndian(uint32_t value) {
    return {char(value >> 24), char(value >> 16), char(value >> 8), char(value)};
}

std::string chunk(const std::string& type, const std::string& data) {
    return bigEndian(uint32_t(data.size())) + type + data + bigEndian(referenceCrc(type + data));
}

// A PNG from encodePng with `extra` chunks inserted after IHDR (8 + 25 bytes).
std::vector<uint8_t> withChunks(const std::string& extra) {
    std::vector<uint8_t> png = encodePng(testImage());
    png.insert(png.begin() + 33, extra.begin(), extra.end());
    return png;
}

Scene unusualScene() {
    Scene scene = defaultScene();
    scene.mesh = MeshKind::Torus;
    scene.material.name = "brushed \"gold\" \xc3\xa9";
    scene.material.baseColor = {1.0f, 0.7812345f, 0.34f};
    scene.material.roughness = 0.0123f;
    scene.material.metallic = 1.0f;
    scene.camera.fovYDegrees = 33.3f;
    scene.display.tonemap = Tonemap::AcesNarkowicz;
    scene.display.exposure = -1.25f;
    scene.lights[0].enabled = false;
    return scene;
}

class PngText : public test::ScratchTest {
protected:
    fs::path save(const std::string& name, const std::vector<uint8_t>& bytes) const {
        writeFileAtomic(dir_ / name, bytes);
        return dir_ / name;
    }

    std::string sceneError(const std::string& name, const std::vector<uint8_t>& bytes) const {
        std::vector<std::string> warnings;
        try {
            sceneFromPng(save(name, bytes), warnings);
        } catch (const InputError& error) {
            return error.what();
        }
        return "";
    }
};

// The encoder (engine/io/file_bytes.cpp, zlib): what stb's independent decoder reads back is every byte
// written, for a single pixel, odd sizes and a wide row (the Sub filter wraps at 256).
TEST(PngEncode, DecodesToTheSameBytes) {
    for (const auto& [width, height] : {std::pair{1, 1}, {5, 3}, {1031, 7}, {3, 400}}) {
        LdrImage image{width, height, std::vector<uint8_t>(size_t(width) * height * 4)};
        uint32_t state = 12345u;
        for (uint8_t& byte : image.rgba) {
            state = state * 1664525u + 1013904223u;
            byte = uint8_t(state >> 24);
        }
        const LdrImage decoded = decodePng(encodePng(image));
        EXPECT_EQ(decoded.width, width);
        EXPECT_EQ(decoded.height, height);
        EXPECT_EQ(decoded.rgba, image.rgba) << width << "x" << height;
    }
    EXPECT_THROW(encodePng(LdrImage{2, 2, std::vector<uint8_t>(3)}), std::runtime_error);
}

// Bands of rows deflated on threads of their own join into one zlib stream: zlib's own
// inflate (which checks the Adler-32 the bands' sums combine into) reads back every row,
// filter byte and all; and as the bands are cut at fixed rows, the bytes are the same
// whatever the number of threads.
TEST(PngEncode, BandsMakeOneValidStreamWhateverTheThreads) {
    const int width = 700, height = 900;   // 2.5 MB raw: three bands of 1 MiB or less
    LdrImage image{width, height, std::vector<uint8_t>(size_t(width) * height * 4)};
    for (size_t i = 0; i < image.rgba.size(); ++i) {
        image.rgba[i] = uint8_t((i / 4 % width) * 3 + (i / 4 / width) * (i % 4 + 1));
    }
    auto idat = [](const std::vector<uint8_t>& png) {
        std::vector<uint8_t> data;
        for (size_t at = kPngSignature.size(); at + 12 <= png.size();) {
            const uint32_t length = readBigEndian32(&png[at]);
            if (std::equal(&png[at + 4], &png[at + 8], "IDAT")) {
                data.insert(data.end(), &png[at + 8], &png[at + 8 + length]);
            }
            at += 12 + length;
        }
        return data;
    };
    const std::vector<uint8_t> one = idat(encodePng(image, 1));
    std::vector<uint8_t> raw(size_t(height) * (size_t(width) * 4 + 1));
    uLongf rawSize = uLongf(raw.size());
    ASSERT_EQ(uncompress(raw.data(), &rawSize, one.data(), uLong(one.size())), Z_OK);
    ASSERT_EQ(rawSize, raw.size());
    for (int y = 0; y < height; ++y) {
        const uint8_t* row = &raw[size_t(y) * (size_t(width) * 4 + 1)];
        ASSERT_EQ(row[0], 1) << "Sub filter, row " << y;
        for (size_t i = 0; i < size_t(width) * 4; ++i) {
            const uint8_t left = i >= 4 ? image.rgba[size_t(y) * width * 4 + i - 4] : 0;
            ASSERT_EQ(uint8_t(row[1 + i] + left), image.rgba[size_t(y) * width * 4 + i]) << "row " << y << ", byte " << i;
        }
    }
    for (unsigned threads : {2u, 3u, 8u}) {
        EXPECT_EQ(idat(encodePng(image, threads)), one) << threads << " threads";
    }
}

// Rows handed on while the rest of the image is still being drawn: the file is the one
// encodePng makes of the finished image, and no row is handed on before it is finished.
TEST(PngEncode, StreamTakesRowsAsTheyAreFinished) {
    const int width = 300, height = 4000;   // 4.8 MB raw: bands of 873 rows
    const LdrImage finished = [&] {
        LdrImage image{width, height, std::vector<uint8_t>(size_t(width) * height * 4)};
        for (size_t i = 0; i < image.rgba.size(); ++i) {
            image.rgba[i] = uint8_t(i * 7 / 5 + i / 4 / width);
        }
        return image;
    }();
    LdrImage drawing{width, height, std::vector<uint8_t>(finished.rgba.size(), 0)};
    PngStream png(drawing, 2);
    for (int rows = 0; rows < height;) {
        const int next = std::min(height, rows + 150);
        std::copy(finished.rgba.begin() + ptrdiff_t(rows) * width * 4, finished.rgba.begin() + ptrdiff_t(next) * width * 4,
                  drawing.rgba.begin() + ptrdiff_t(rows) * width * 4);
        rows = next;
        png.rowsReady(rows);
        EXPECT_LE(png.rowsHandedOn(), rows);   // never a row still to be drawn
    }
    EXPECT_GT(png.rowsHandedOn(), 0) << "rows deflated while the rest was drawn";
    EXPECT_EQ(png.finish(), encodePng(finished));
    EXPECT_THROW(png.finish(), std::logic_error);
    EXPECT_THROW(PngStream(LdrImage{2, 2, std::vector<uint8_t>(3)}), std::runtime_error);
}

TEST_F(PngText, RoundTripsEntriesAndKeepsThePixels) {
    const std::vector<std::pair<std::string, std::string>> text{
        {"Title", "a sphere"}, {"Comment", "caf\xc3\xa9 \xe2\x9c\x93\nline two"}, {"Empty", ""}};
    const std::vector<uint8_t> png = encodePngWithText(testImage(), text);
    const std::map<std::string, std::string> read = readPngText(png);
    ASSERT_EQ(read.size(), 3u);
    for (const auto& [keyword, value] : text) {
        EXPECT_EQ(read.at(keyword), value) << keyword;
    }
    EXPECT_EQ(decodePng(png).rgba, testImage().rgba);
}

TEST_F(PngText, WritesUncompressedInternationalTextRightAfterIhdr) {
    const std::vector<uint8_t> png = encodePngWithText(testImage(), {{"k", "v"}});
    const std::string data("k\0\0\0\0\0v", 7);
    const std::string expected = chunk("iTXt", data);   // its CRC computed independently
    ASSERT_GT(png.size(), 33 + expected.size());
    EXPECT_EQ(std::string(png.begin() + 12, png.begin() + 16), "IHDR");
    EXPECT_EQ(std::string(png.begin() + 33, png.begin() + 33 + std::ptrdiff_t(expected.size())),
              expected);
}

TEST_F(PngText, ReadsLatinOneTextAndSkipsCompressedText) {
    const std::string compressed("zipped\0\1\0\0\0\x78\x9c", 13);
    const std::vector<uint8_t> png =
        withChunks(chunk("tEXt", std::string("Author\0caf\xe9", 11)) + chunk("iTXt", compressed));
    const std::map<std::string, std::string> read = readPngText(png);
    EXPECT_EQ(read.size(), 1u);
    EXPECT_EQ(read.at("Author"), "caf\xc3\xa9");
}

TEST_F(PngText, TheFirstOfARepeatedKeywordWins) {
    const std::vector<uint8_t> png = encodePngWithText(testImage(), {{"k", "first"}, {"k", "second"}});
    EXPECT_EQ(readPngText(png).at("k"), "first");
}

TEST_F(PngText, RefusesBadKeywordsAndText) {
    for (const std::string& keyword :
         {std::string(), std::string(80, 'k'), std::string(" lead"), std::string("trail "),
          std::string("two  spaces"), std::string("tab\there"), std::string("nul\0x", 5),
          std::string("del\x7f"), std::string("nbsp\xa0")}) {
        EXPECT_THROW(encodePngWithText(testImage(), {{keyword, "v"}}), std::invalid_argument)
            << keyword;
    }
    EXPECT_NO_THROW(encodePngWithText(testImage(), {{std::string(79, 'k'), "v"}}));
    EXPECT_NO_THROW(encodePngWithText(testImage(), {{"Latin-1 \xe9t\xe9", "v"}}));
    for (const std::string text : {"\xff", "\xc3", "\xc0\xaf", "\xed\xa0\x80", "\xf4\x90\x80\x80"}) {
        EXPECT_THROW(encodePngWithText(testImage(), {{"k", text}}), std::invalid_argument);
    }
}

TEST_F(PngText, RestoresTheSameSceneExactly) {
    const Scene scene = unusualScene();
    const std::string json = prettyJson(sceneToJson(scene));
    const fs::path file =
        save("scene.png", encodePngWithText(testImage(), {{kSceneTextKeyword, json}}));
    std::vector<std::string> warnings;
    const std::optional<Scene> restored = sceneFromPng(file, warnings);
    ASSERT_TRUE(restored.has_value());
    EXPECT_EQ(*restored, scene);
    EXPECT_NE(*restored, defaultScene());
    EXPECT_TRUE(warnings.empty());
}

TEST_F(PngText, APngWithoutASceneGivesNothing) {
    std::vector<std::string> warnings;
    const fs::path plain = save("plain.png", encodePng(testImage()));
    EXPECT_FALSE(sceneFromPng(plain, warnings).has_value());
    const fs::path other = save("other.png", encodePngWithText(testImage(), {{"Title", "x"}}));
    EXPECT_FALSE(sceneFromPng(other, warnings).has_value());
}

TEST_F(PngText, RefusesCorruptedChunks) {
    std::vector<uint8_t> png = encodePngWithText(testImage(), {{"k", "some text"}});
    png[33 + 8 + 8] ^= 0x01;   // a byte of the text: the CRC no longer matches
    try {
        readPngText(png);
        FAIL() << "a corrupted chunk was accepted";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("chunk 'iTXt' fails its CRC-32 check"),
                  std::string::npos) << error.what();
        EXPECT_NE(std::string(error.what()).find("at byte 33"), std::string::npos) << error.what();
    }
    EXPECT_NE(sceneError("bad_crc.png", png).find("bad_crc.png: malformed PNG"), std::string::npos);
}

TEST_F(PngText, RefusesEveryTruncation) {
    const std::vector<uint8_t> png = encodePngWithText(testImage(), {{"k", "some text"}});
    ASSERT_NO_THROW(readPngText(png));
    for (size_t size = 0; size < png.size(); ++size) {
        const std::vector<uint8_t> cut(png.begin(), png.begin() + std::ptrdiff_t(size));
        EXPECT_THROW(readPngText(cut), InputError) << size << " bytes";
    }
}

TEST_F(PngText, RefusesHostileChunkHeaders) {
    const std::vector<uint8_t> png = encodePng(testImage());
    std::vector<uint8_t> huge = png;
    huge[33] = huge[34] = huge[35] = huge[36] = 0xFF;   // the chunk after IHDR claims 4 GiB
    EXPECT_THROW(readPngText(huge), InputError);
    std::vector<uint8_t> badType = png;
    badType[38] = '?';
    EXPECT_THROW(readPngText(badType), InputError);
    // Text chunks whose fields run past their end.
    for (const std::string& data : {std::string("no terminator"), std::string("\0empty", 6),
                                   std::string("k\0", 2), std::string("k\0\0\0lang", 8),
                                   std::string("k\0\0\0lang\0trans", 14),
                                   std::string("k\0\2\0\0\0x", 7), std::string("k\0\0\0\0\0\xff", 7)}) {
        EXPECT_THROW(readPngText(withChunks(chunk("iTXt", data))), InputError) << data;
    }
    EXPECT_THROW(readPngText(withChunks(chunk("tEXt", "no terminator"))), InputError);
    EXPECT_THROW(readPngText(withChunks(chunk("tEXt", std::string(80, 'k') + '\0'))), InputError);
    // A valid chunk stream that does not start with IHDR.
    std::vector<uint8_t> noHeader(png.begin(), png.begin() + 8);
    const std::string end = chunk("IEND", "");
    noHeader.insert(noHeader.end(), end.begin(), end.end());
    EXPECT_THROW(readPngText(noHeader), InputError);
}

TEST_F(PngText, RefusesEverySingleByteChange) {
    // Signature, lengths, types, data and CRCs: nothing follows IEND, so every change shows.
    const std::vector<uint8_t> png = encodePngWithText(testImage(), {{"k", "text"}});
    for (size_t i = 0; i < png.size(); ++i) {
        for (const uint8_t value : {uint8_t(0x00), uint8_t(0x80), uint8_t(0xFF)}) {
            std::vector<uint8_t> changed = png;
            changed[i] = value;
            if (changed != png) {
                EXPECT_THROW(readPngText(changed), InputError) << "byte " << i;
            }
        }
    }
}

TEST_F(PngText, RefusesFilesThatAreNotPngs) {
    const std::string json = "{\"format\": \"patina-scene\", \"version\": 1}";
    const std::string error = sceneError("scene.json", std::vector<uint8_t>(json.begin(), json.end()));
    EXPECT_NE(error.find("scene.json: not a PNG file"), std::string::npos) << error;
    EXPECT_NE(sceneError("empty.png", {}).find("not a PNG file"), std::string::npos);
    std::vector<std::string> warnings;
    EXPECT_THROW(sceneFromPng(dir_ / "missing.png", warnings), InputError);
    // Only a regular file is read: not a folder, nor /dev/zero for ever.
    fs::create_directory(dir_ / "folder.png");
    try {
        sceneFromPng(dir_ / "folder.png", warnings);
        ADD_FAILURE() << "a folder was read as a PNG";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("folder.png: a folder, not a file"), std::string::npos);
    }
    // Sparse: the size is refused before a byte is read, and it costs no disk.
    std::ofstream(dir_ / "huge.png").close();
    fs::resize_file(dir_ / "huge.png", uint64_t(600) << 20);
    try {
        sceneFromPng(dir_ / "huge.png", warnings);
        ADD_FAILURE() << "a 600 MiB PNG was read";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("huge.png: the file is 600 MiB; PNGs with a scene are limited to 512 MiB"),
                  std::string::npos) << error.what();
    }
}

TEST_F(PngText, RefusesABadEmbeddedScene) {
    auto withScene = [](const std::string& json) {
        return encodePngWithText(testImage(), {{kSceneTextKeyword, json}});
    };
    std::string error = sceneError("syntax.png", withScene("{\"format\": "));
    EXPECT_NE(error.find("syntax.png (patina-scene):1:"), std::string::npos) << error;
    error = sceneError("value.png", withScene(R"({"format": "patina-scene", "version": 1,
                                                  "material": {"roughness": 3}})"));
    EXPECT_NE(error.find("value.png (patina-scene): /material/roughness"), std::string::npos) << error;
    error = sceneError("path.png", withScene(R"({"format": "patina-scene", "version": 1,
                                                 "material": "../../etc/passwd"})"));
    EXPECT_NE(error.find("/material: an embedded scene must hold its material inline"),
              std::string::npos) << error;
}

}  // namespace
}  // namespace patina
