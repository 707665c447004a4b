// Material files: notes, unknown keys kept for saving, required keys, the version.
#include <gtest/gtest.h>

#include "scene_file.h"

namespace patina {
namespace {

Material read(const std::string& text, std::vector<std::string>& warnings) {
    return materialFromJson(parseJsonText(text, "m.json"), "", "m.json", true, warnings);
}

std::string errorOf(const std::string& text) {
    std::vector<std::string> warnings;
    try {
        read(text, warnings);
    } catch (const InputError& error) {
        return error.what();
    }
    return "";
}

TEST(MaterialFile, NotesRoundTripAndAreLeftOutWhenEmpty) {
    Material material;
    EXPECT_FALSE(materialToJson(material).contains("notes"));
    material.notes = "F0 from somewhere, 2024";
    const Json json = materialToJson(material);
    EXPECT_EQ(json["notes"], "F0 from somewhere, 2024");
    std::vector<std::string> warnings;
    EXPECT_EQ(materialFromJson(json, "", "x", true, warnings), material);
    EXPECT_TRUE(warnings.empty());
    EXPECT_NE(errorOf(R"({"format": "patina-material", "version": 1, "notes": 5})")
                  .find("m.json: /notes: expected a string"), std::string::npos);
}

TEST(MaterialFile, UnknownKeysAreWarnedAboutAndWrittenBack) {
    std::vector<std::string> warnings;
    const Material material = read(R"({"format": "patina-material", "version": 1,
        "author": "me", "roughness": 0.2, "layers": {"clearcoat": [1, 0.1]}})", warnings);
    ASSERT_EQ(warnings.size(), 2u);
    EXPECT_EQ(warnings[0], "m.json: /author: unknown key 'author' (kept, not used)");
    EXPECT_NE(warnings[1].find("/layers: unknown key"), std::string::npos);
    const Json written = materialToJson(material);
    EXPECT_EQ(written["author"], "me");
    EXPECT_EQ(written["layers"], Json::parse(R"({"clearcoat": [1, 0.1]})"));
    EXPECT_FLOAT_EQ(written["roughness"].get<float>(), 0.2f);
    EXPECT_EQ(materialFromJson(written, "", "x", true, warnings), material);
}

TEST(MaterialFile, ExtrasTakePartInEqualityButNeverOverrideKnownKeys) {
    Material a, b;
    b.extras["author"] = "me";
    EXPECT_NE(a, b);
    b.extras = Json::object({{"roughness", 0.9}});
    EXPECT_FLOAT_EQ(materialToJson(b)["roughness"].get<float>(), b.roughness);
}

TEST(MaterialFile, FormatAndVersionAreRequiredInAFileButOptionalInline) {
    EXPECT_NE(errorOf(R"({"version": 1, "roughness": 0.2})")
                  .find("m.json: /: missing required key 'format'"), std::string::npos);
    EXPECT_NE(errorOf(R"({"format": "patina-material", "roughness": 0.2})")
                  .find("m.json: /: missing required key 'version'"), std::string::npos);
    std::vector<std::string> warnings;
    EXPECT_NO_THROW(materialFromJson(Json::parse(R"({"roughness": 0.2})"), "/material", "s.json",
                                     false, warnings));
    try {
        materialFromJson(Json::parse(R"({"version": 1})"), "/material", "s.json", false, warnings);
        ADD_FAILURE() << "version without format";
    } catch (const InputError& error) {
        EXPECT_STREQ(error.what(), "s.json: /material: missing required key 'format'");
    }
}

TEST(MaterialFile, VersionIsAnIntegerUpToTheSupportedOne) {
    EXPECT_EQ(errorOf(R"({"format": "patina-material", "version": 1.0})"), "");
    EXPECT_NE(errorOf(R"({"format": "patina-material", "version": 1.5})")
                  .find("m.json: /version: expected an integer, got 1.5"), std::string::npos);
    EXPECT_EQ(errorOf(R"({"format": "patina-material", "version": 2})"),
              "m.json: /version: version 2 is newer than this Patina reads (up to 1)");
    EXPECT_NE(errorOf(R"({"format": "patina-material", "version": 0})").find("/version: value 0"),
              std::string::npos);
}

}  // namespace
}  // namespace patina
