// Material and scene JSON made to hurt: deep nesting, huge files and strings, files that are
// not files, and every JSON type at every place. Each is refused with an InputError that names
// the file; nothing crashes, hangs or reads without bound.
#include <fstream>
#include <sys/stat.h>

#include <gtest/gtest.h>

#include "io/json_writer.h"
#include "picture/png_text.h"
#include "io/scene_file.h"
#include "scratch_test.h"

namespace patina {
namespace {

namespace fs = std::filesystem;

const std::string kMaterialHead = R"({"format": "patina-material", "version": 1, )";
const std::string kSceneHead = R"({"format": "patina-scene", "version": 1, )";

std::string nested(size_t depth) {
    return std::string(depth, '[') + std::string(depth, ']');
}

class HostileJson : public test::ScratchTest {
protected:
    // The InputError's message for loading `text` from a file; "(loaded)" when it loads.
    std::string loadError(const std::string& text, bool scene) const {
        write("f.json", text);
        std::vector<std::string> warnings;
        try {
            if (scene) {
                loadSceneFile(path("f.json"), warnings);
            } else {
                loadMaterialFile(path("f.json"), warnings);
            }
        } catch (const InputError& error) {
            return error.what();
        }
        return "(loaded)";
    }
};

#define EXPECT_ERROR(message, part) \
    EXPECT_NE(std::string(message).find(part), std::string::npos) << "message: " << (message)

// nlohmann copies (a material's unknown keys), compares and dumps (messages) recursively:
// a million levels overflowed the stack before the parser limited nesting.
TEST_F(HostileJson, DeepNestingIsRefusedNotAStackOverflow) {
    const std::string deep = nested(1'000'000);
    EXPECT_ERROR(loadError(kMaterialHead + R"("extra": )" + deep + "}", false),
                 path("f.json").string() + ": JSON nested deeper than 64 levels");
    EXPECT_ERROR(loadError(kSceneHead + R"("lights": [{"type": )" + deep + "}]}", true),
                 "JSON nested deeper than 64 levels");
    EXPECT_ERROR(loadError(kSceneHead + R"("material": {"x": )" + deep + "}}", true),
                 "JSON nested deeper than 64 levels");
    // Within the limit, unknown nested keys still load and are kept.
    EXPECT_EQ(loadError(kMaterialHead + R"("extra": )" + nested(62) + "}", false), "(loaded)");
    EXPECT_EQ(loadError(kSceneHead + R"("material": {"extra": )" + nested(62) + "}}", true), "(loaded)");
    EXPECT_ERROR(loadError(kSceneHead + R"("material": {"extra": )" + nested(63) + "}}", true), "deeper than 64");
}

// A material file may nest one level less than the parser allows: saved inline in a scene, as
// a screenshot does, it must load again (tests/fuzz/fuzz_material.cpp checks this too).
TEST_F(HostileJson, EveryMaterialThatLoadsFitsInsideAScene) {
    EXPECT_ERROR(loadError(kMaterialHead + R"("extra": )" + nested(63) + "}", false),
                 path("f.json").string() + ": /extra: nested deeper than 62 levels (a material must fit inside a scene)");
    std::vector<std::string> warnings;
    Scene scene = defaultScene();
    write("m.json", kMaterialHead + R"("extra": [{"a": )" + nested(60) + "}]}");
    scene.material = loadMaterialFile(path("m.json"), warnings);
    EXPECT_EQ(sceneFromJson(parseJsonText(prettyJson(sceneToJson(scene)), "s.json"), "s.json", dir_, warnings),
              scene);
}

// Written a megabyte at a time: the test itself never holds the 100 MB.
TEST_F(HostileJson, AHundredMegabyteStringIsRefusedBeforeItIsRead) {
    for (const bool scene : {false, true}) {
        {
            std::ofstream file(path("big.json"), std::ios::binary);
            file << (scene ? kSceneHead : kMaterialHead) << R"("name": ")";
            const std::string megabyte(size_t(1) << 20, 'a');
            for (int i = 0; i < 100; ++i) {
                file << megabyte;
            }
            file << "\"}";
        }
        std::vector<std::string> warnings;
        try {
            scene ? (void)loadSceneFile(path("big.json"), warnings)
                  : (void)loadMaterialFile(path("big.json"), warnings);
            ADD_FAILURE() << "a 100 MB file loaded";
        } catch (const InputError& error) {
            EXPECT_ERROR(error.what(), path("big.json").string() +
                                           ": the file is 101 MiB; Patina's JSON files are limited to 4 MiB");
        }
    }
}

TEST_F(HostileJson, TextOverTheLimitIsRefusedWhereverItComesFrom) {
    const std::string text = kSceneHead + R"("x": ")" + std::string(kMaxJsonFileBytes, 'a') + "\"}";
    try {
        parseJsonText(text, "s.json");
        ADD_FAILURE() << "text over the limit parsed";
    } catch (const InputError& error) {
        EXPECT_STREQ(error.what(), "s.json: 5 MiB of JSON; Patina reads at most 4 MiB");
    }
    // A PNG's scene is held to the same limit.
    LdrImage image{1, 1, {0, 0, 0, 255}};
    std::vector<std::string> warnings;
    try {
        sceneFromPngBytes(encodePngWithText(image, {{kSceneTextKeyword, text}}), "s.png", warnings);
        ADD_FAILURE() << "a scene over the limit loaded from a PNG";
    } catch (const InputError& error) {
        EXPECT_STREQ(error.what(), "s.png (patina-scene): 5 MiB of JSON; Patina reads at most 4 MiB");
    }
}

TEST_F(HostileJson, LongValuesAreCutInMessages) {
    const std::string longName(1'000'000, 'x');
    const std::string error = loadError(kMaterialHead + R"("model": ")" + longName + "\"}", false);
    EXPECT_ERROR(error, "/model: unknown BRDF model \"xxxx");
    EXPECT_ERROR(error, "xxx...");
    EXPECT_LT(error.size(), 1000u);
    EXPECT_LT(loadError(kSceneHead + R"("lights": [{"type": [")" + longName + "\"]}]}", true).size(), 300u);
    EXPECT_LT(loadError(R"({"format": ")" + longName + R"(", "version": 1})", false).size(), 300u);
    // Cut between characters, not inside one: "\xc3\xa9" is one.
    std::string accents;
    for (int i = 0; i < 20; ++i) {
        accents += "\xc3\xa9";
    }
    const std::string cut = loadError(kMaterialHead + R"("model": ")" + std::string(58, 'a') + accents + "\"}", false);
    EXPECT_ERROR(cut, "\"" + std::string(58, 'a') + "...");
}

// Found by tests/fuzz: nlohmann throws out_of_range, not parse_error, for a number a double
// cannot hold, and it escaped the loaders (the CLI exited 1 with nlohmann's own message).
TEST_F(HostileJson, NumbersBeyondADoubleAreInputErrors) {
    try {
        parseJsonText(R"({"format": "patina-material", "version": 1e391.0})", "m.json");
        ADD_FAILURE() << "1e391 parsed";
    } catch (const InputError& error) {
        EXPECT_STREQ(error.what(), "m.json: invalid JSON: number overflow parsing '1e391'");
    }
    EXPECT_ERROR(loadError(kSceneHead + R"("camera": {"fovYDegrees": -)" + std::string(100'000, '9') + "}}", true),
                 ": invalid JSON: number overflow parsing '-9999");
    EXPECT_LT(loadError(kSceneHead + R"("camera": {"fovYDegrees": -)" + std::string(100'000, '9') + "}}", true)
                  .size(), 400u);
    // A syntax error quotes the token too: cut as well.
    const std::string unterminated = loadError(kSceneHead + R"("mesh": ")" + std::string(100'000, 'x'), true);
    EXPECT_ERROR(unterminated, ":1:");
    EXPECT_LT(unterminated.size(), 400u);
}

// A material path in a scene may name anything: only a regular file is read, so /dev/zero
// cannot be read forever, nor a FIFO wait forever. The FIFO is made here rather than taking
// /dev/null, which some sandboxes (CI's among them) bind to a regular file.
TEST_F(HostileJson, OnlyRegularFilesAreRead) {
    fs::create_directory(path("folder.json"));
    ASSERT_EQ(mkfifo(path("pipe.json").c_str(), 0600), 0);
    EXPECT_ERROR(loadError(kSceneHead + R"("material": ")" + path("folder.json").string() + "\"}", true),
                 path("folder.json").string() + ": a folder, not a file");
    EXPECT_ERROR(loadError(kSceneHead + R"("material": ")" + path("pipe.json").string() + "\"}", true),
                 path("pipe.json").string() + ": not a regular file");
    std::vector<std::string> warnings;
    EXPECT_THROW(loadMaterialFile(path("pipe.json"), warnings), InputError);
}

// Every place in a full scene (material inline, every light type) and in a material, given
// every kind of JSON value: it loads, or it is an InputError naming the file.
TEST_F(HostileJson, EveryJsonTypeAtEveryPlace) {
    Scene scene = defaultScene();
    scene.material.notes = "notes";
    ASSERT_GE(scene.lights.size(), 3u);
    const Json values[] = {nullptr, true, 0, -1, 1.5, 1e300, "", "sphere", Json::array(),
                           Json::array({0, 0, 0}), Json::object(), Json::object({{"type", "point"}})};
    size_t loaded = 0, refused = 0;
    for (const bool isScene : {false, true}) {
        const Json full = isScene ? sceneToJson(scene) : materialToJson(scene.material);
        const Json flat = full.flatten();
        std::vector<std::string> pointers;
        for (auto it = flat.begin(); it != flat.end(); ++it) {
            for (Json::json_pointer at(it.key()); !at.empty(); at = at.parent_pointer()) {
                pointers.push_back(at.to_string());
            }
        }
        pointers.push_back("");
        for (const std::string& pointer : pointers) {
            for (const Json& value : values) {
                Json document = full;
                document[Json::json_pointer(pointer)] = value;
                std::vector<std::string> warnings;
                try {
                    isScene ? (void)sceneFromJson(document, "t.json", dir_, warnings)
                            : (void)materialFromJson(document, "", "t.json", true, warnings);
                    ++loaded;
                } catch (const InputError& error) {
                    // A string "material" is a path: then the message names that file.
                    const std::string message = error.what();
                    EXPECT_TRUE(message.rfind("t.json: ", 0) == 0 || message.rfind(dir_.string(), 0) == 0)
                        << message;
                    ++refused;
                }
            }
        }
    }
    EXPECT_GT(refused, 400u);
    EXPECT_GT(loaded, 20u);
}

}  // namespace
}  // namespace patina
