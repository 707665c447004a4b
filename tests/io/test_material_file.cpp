// Material files: notes, unknown keys kept for saving, required keys, the version; and the
// shipped presets.
#include <regex>

#include <gtest/gtest.h>

#include "files/input_error.h"
#include "io/scene_file.h"
#include "scratch_test.h"

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

// KHR_materials_clearcoat's factors: written only where there is a coat (a material without
// one is written as before the extension, so screenshots' scenes keep their bytes), read back
// the same, checked as every factor.
TEST(MaterialFile, TheClearcoatRoundTripsAndIsLeftOutWithoutACoat) {
    Material material;
    EXPECT_FALSE(materialToJson(material).contains("clearcoat"));
    EXPECT_FALSE(materialToJson(material).contains("clearcoatRoughness"));
    material.clearcoat = 0.75f;
    material.clearcoatRoughness = 0.125f;
    const Json json = materialToJson(material);
    EXPECT_EQ(json["clearcoat"], 0.75);
    EXPECT_EQ(json["clearcoatRoughness"], 0.125);
    std::vector<std::string> warnings;
    EXPECT_EQ(materialFromJson(json, "", "x", true, warnings), material);
    EXPECT_TRUE(warnings.empty());
    EXPECT_NE(errorOf(R"({"format": "patina-material", "version": 1, "clearcoat": 1.5})").find("m.json: /clearcoat"),
              std::string::npos);
}

// KHR_materials_sheen's factors, as the coat's: written only where there is a sheen, read back
// the same, checked as every factor.
TEST(MaterialFile, TheSheenRoundTripsAndIsLeftOutWithoutOne) {
    Material material;
    EXPECT_FALSE(materialToJson(material).contains("sheenColor"));
    EXPECT_FALSE(materialToJson(material).contains("sheenRoughness"));
    material.sheenColor = {0.75f, 0.5f, 0.125f};
    material.sheenRoughness = 0.375f;
    const Json json = materialToJson(material);
    EXPECT_EQ(json["sheenColor"], Json::array({0.75, 0.5, 0.125}));
    EXPECT_EQ(json["sheenRoughness"], 0.375);
    std::vector<std::string> warnings;
    EXPECT_EQ(materialFromJson(json, "", "x", true, warnings), material);
    EXPECT_TRUE(warnings.empty());
    Material roughOnly;
    roughOnly.sheenRoughness = 0.5f;   // a roughness without colour is kept too
    EXPECT_EQ(materialFromJson(materialToJson(roughOnly), "", "x", true, warnings), roughOnly);
    EXPECT_NE(errorOf(R"({"format": "patina-material", "version": 1, "sheenColor": [1, 2, 0]})").find("m.json: /sheenColor"),
              std::string::npos);
    EXPECT_NE(errorOf(R"({"format": "patina-material", "version": 1, "sheenRoughness": -1})").find("m.json: /sheenRoughness"),
              std::string::npos);
}

// A volume set without a transmission (yet) is kept when the material is saved: the fuzzer's
// amber glass, its "transmission" key misspelt, lost its thickness and attenuation on a save.
TEST(MaterialFile, AVolumeWithoutATransmissionIsKeptWhenSaved) {
    std::vector<std::string> warnings;
    const Material read_back = read(R"({"format": "patina-material", "version": 1, "thickness": 0.5,
        "attenuationColor": [1, 0.6, 0.2], "attenuationDistance": 0.25})", warnings);
    const Json json = materialToJson(read_back);
    EXPECT_FALSE(json.contains("transmission"));
    EXPECT_EQ(json["thickness"], 0.5);
    EXPECT_EQ(materialFromJson(json, "", "x", true, warnings), read_back);
    Material colourOnly;
    colourOnly.attenuationColor = {0.5f, 1.0f, 1.0f};
    EXPECT_EQ(materialFromJson(materialToJson(colourOnly), "", "x", true, warnings), colourOnly);
}

// KHR_materials_anisotropy's strength and rotation: written only where the lobe is stretched,
// read back the same, the strength checked as every factor.
TEST(MaterialFile, TheAnisotropyRoundTripsAndIsLeftOutWithoutOne) {
    Material material;
    for (const char* key : {"anisotropyStrength", "anisotropyRotation"}) {
        EXPECT_FALSE(materialToJson(material).contains(key)) << key;
    }
    // A rotation without a strength draws nothing but is what the file said: it comes back (the
    // material fuzzer found it dropped on save).
    material.anisotropyRotation = 0.25f;
    EXPECT_FALSE(materialToJson(material).contains("anisotropyStrength"));
    std::vector<std::string> kept;
    EXPECT_EQ(materialFromJson(materialToJson(material), "", "x", true, kept), material);
    material.anisotropyStrength = 0.75f;
    material.anisotropyRotation = -1.5f;
    const Json json = materialToJson(material);
    EXPECT_EQ(json["anisotropyStrength"], 0.75);
    EXPECT_EQ(json["anisotropyRotation"], -1.5);
    std::vector<std::string> warnings;
    EXPECT_EQ(materialFromJson(json, "", "x", true, warnings), material);
    EXPECT_TRUE(warnings.empty());
    EXPECT_NE(errorOf(R"({"format": "patina-material", "version": 1, "anisotropyStrength": 1.5})")
                  .find("m.json: /anisotropyStrength"),
              std::string::npos);
}

// KHR_materials_specular's tint and weight: each written only where it is not its default, read
// back the same; the tint up to 12.5 (F0 1 at specular 1), the weight a factor in [0, 1].
TEST(MaterialFile, TheSpecularTintAndWeightRoundTripAndAreLeftOutWithoutThem) {
    Material material;
    for (const char* key : {"specularTint", "specularWeight"}) {
        EXPECT_FALSE(materialToJson(material).contains(key)) << key;
    }
    material.specularTint = {12.5f, 1.0f, 0.25f};
    std::vector<std::string> warnings;
    EXPECT_FALSE(materialToJson(material).contains("specularWeight"));
    EXPECT_EQ(materialFromJson(materialToJson(material), "", "x", true, warnings), material);
    material.specularWeight = 0.5f;
    const Json json = materialToJson(material);
    EXPECT_EQ(json["specularTint"], Json::array({12.5, 1.0, 0.25}));
    EXPECT_EQ(json["specularWeight"], 0.5);
    EXPECT_EQ(materialFromJson(json, "", "x", true, warnings), material);
    EXPECT_TRUE(warnings.empty());
    EXPECT_NE(errorOf(R"({"format": "patina-material", "version": 1, "specularTint": [13, 1, 1]})")
                  .find("m.json: /specularTint"),
              std::string::npos);
    EXPECT_NE(errorOf(R"({"format": "patina-material", "version": 1, "specularWeight": -0.5})")
                  .find("m.json: /specularWeight"),
              std::string::npos);
}

// KHR_materials_iridescence's four: written together wherever one is not its default, read back
// the same, each checked (the ior at least 1, the thicknesses not below 0).
TEST(MaterialFile, TheFilmRoundTripsAndIsLeftOutWithoutOne) {
    Material material;
    for (const char* key : {"iridescence", "iridescenceIor", "iridescenceThicknessMinimum", "iridescenceThicknessMaximum"}) {
        EXPECT_FALSE(materialToJson(material).contains(key)) << key;
    }
    material.iridescence = 0.5f;
    material.iridescenceIor = 1.75f;
    material.iridescenceThicknessMaximum = 640.0f;
    const Json json = materialToJson(material);
    EXPECT_EQ(json["iridescence"], 0.5);
    EXPECT_EQ(json["iridescenceThicknessMinimum"], 100.0);
    std::vector<std::string> warnings;
    EXPECT_EQ(materialFromJson(json, "", "x", true, warnings), material);
    EXPECT_TRUE(warnings.empty());
    EXPECT_NE(errorOf(R"({"format": "patina-material", "version": 1, "iridescenceIor": 0.9})").find("m.json: /iridescenceIor"),
              std::string::npos);
    EXPECT_NE(errorOf(R"({"format": "patina-material", "version": 1, "iridescenceThicknessMaximum": -1})")
                  .find("m.json: /iridescenceThicknessMaximum"),
              std::string::npos);
}

// KHR_materials_transmission's and KHR_materials_volume's factors: written only where set,
// read back the same, checked as every factor (the thickness and distance not below 0).
TEST(MaterialFile, TheTransmissionAndVolumeRoundTripAndAreLeftOutWithoutOne) {
    Material material;
    for (const char* key : {"transmission", "thickness", "attenuationColor", "attenuationDistance"}) {
        EXPECT_FALSE(materialToJson(material).contains(key)) << key;
    }
    material.transmission = 0.75f;
    material.thickness = 2.5f;
    material.attenuationColor = {1.0f, 0.5f, 0.25f};
    material.attenuationDistance = 0.125f;
    const Json json = materialToJson(material);
    EXPECT_EQ(json["transmission"], 0.75);
    EXPECT_EQ(json["thickness"], 2.5);
    EXPECT_EQ(json["attenuationColor"], Json::array({1.0, 0.5, 0.25}));
    EXPECT_EQ(json["attenuationDistance"], 0.125);
    std::vector<std::string> warnings;
    EXPECT_EQ(materialFromJson(json, "", "x", true, warnings), material);
    EXPECT_TRUE(warnings.empty());
    EXPECT_NE(errorOf(R"({"format": "patina-material", "version": 1, "transmission": 1.5})").find("m.json: /transmission"),
              std::string::npos);
    EXPECT_NE(errorOf(R"({"format": "patina-material", "version": 1, "thickness": -1})").find("m.json: /thickness"),
              std::string::npos);
    EXPECT_NE(errorOf(R"({"format": "patina-material", "version": 1, "attenuationColor": [1, 2, 0]})")
                  .find("m.json: /attenuationColor"),
              std::string::npos);
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

std::vector<std::pair<std::filesystem::path, Material>> shippedPresets() {
    std::vector<std::pair<std::filesystem::path, Material>> presets;
    for (const auto& entry :
         std::filesystem::directory_iterator(std::filesystem::path(PATINA_SOURCE_DIR) / "presets")) {
        if (entry.path().extension() == ".json") {
            std::vector<std::string> warnings;
            presets.emplace_back(entry.path(), loadMaterialFile(entry.path(), warnings));
        }
    }
    return presets;
}

TEST(ShippedPresets, AtLeastTwentyFourAndEachSaysWhereItsNumbersComeFrom) {
    const auto presets = shippedPresets();
    EXPECT_GE(presets.size(), 24u);
    for (const auto& [file, material] : presets) {
        EXPECT_GT(material.notes.size(), 40u) << file;
        EXPECT_TRUE(material.extras.empty()) << file;
    }
}

// Metals take F0 as their base colour; a dielectric's specular is its IOR's F0 / 0.08.
TEST(ShippedPresets, DielectricSpecularMatchesTheIorItsNotesCite) {
    const std::regex ior("IOR ([0-9]+\\.[0-9]+)");
    for (const auto& [file, material] : shippedPresets()) {
        std::smatch match;
        if (material.metallic == 1.0f) {
            EXPECT_NE(material.notes.find("F0"), std::string::npos) << file;
            continue;
        }
        ASSERT_TRUE(std::regex_search(material.notes, match, ior)) << file << ": no IOR in the notes";
        const double n = std::stod(match[1]);
        const double f0 = (n - 1.0) * (n - 1.0) / ((n + 1.0) * (n + 1.0));
        EXPECT_NEAR(material.specular, f0 / 0.08, 5e-4) << file;
        EXPECT_EQ(material.metallic, 0.0f) << file;
    }
}

// Issue 36: presets carry layers. A coat, a sheen, a thin film and a transmission (the glass, and
// the water with its volume's absorption) each have a shipped preset, on the `gltf` model that
// draws them.
TEST(ShippedPresets, TheLayersHavePresetsOnTheModelThatDrawsThem) {
    int coated = 0, sheened = 0, filmed = 0, transmitting = 0, absorbing = 0;
    for (const auto& [file, material] : shippedPresets()) {
        const bool coat = material.clearcoat > 0.0f, sheen = material.sheenColor != glm::vec3(0.0f);
        const bool film = material.iridescence > 0.0f, through = material.transmission > 0.0f;
        coated += coat;
        sheened += sheen;
        filmed += film;
        transmitting += through;
        absorbing += through && material.thickness > 0.0f && material.attenuationDistance > 0.0f;
        if (coat || sheen || film || through) {
            EXPECT_EQ(material.model, BrdfModelId::Gltf) << file;
        }
    }
    EXPECT_GE(coated, 1);
    EXPECT_GE(sheened, 1);
    EXPECT_GE(filmed, 1);
    EXPECT_GE(transmitting, 2);
    EXPECT_GE(absorbing, 1);
}

}  // namespace
}  // namespace patina

namespace patina {
namespace {

class MaterialFolder : public test::ScratchTest {};

// A file of another kind given as a material is named as such, not as a JSON syntax error at
// its first byte: an .obj, an empty file, a glTF model.
TEST_F(MaterialFolder, AFileOfAnotherKindIsSaidToBeOne) {
    std::vector<std::string> warnings;
    auto error = [&](const std::string& name) {
        try {
            loadMaterialFile(path(name), warnings);
        } catch (const InputError& thrown) {
            return std::string(thrown.what());
        }
        return std::string("no error");
    };
    write("ball.obj", "v 0 0 0\nv 1 0 0\n");
    EXPECT_EQ(error("ball.obj"), path("ball.obj").string() + ": not a JSON file: Patina's materials and scenes are JSON");
    write("empty.json", "  \n");
    EXPECT_NE(error("empty.json").find("not a JSON file (it is empty)"), std::string::npos) << error("empty.json");
    write("box.gltf", R"({"asset": {"version": "2.0"}})");
    EXPECT_NE(error("box.gltf").find("box.gltf: a glTF model, not a material"), std::string::npos) << error("box.gltf");
    write("ok.json", R"({"format": "patina-material", "version": 1, "name": "ok"})");
    EXPECT_EQ(error("ok.json"), "no error");
}

// The preset library's listing (editor presets panel, bench-render's batch): .json files only,
// sorted; a missing folder lists nothing rather than throwing.
TEST_F(MaterialFolder, ListsJsonFilesSorted) {
    write("b.json", "{}");
    write("a.json", "{}");
    write("notes.txt", "not a material");
    std::filesystem::create_directories(path("sub"));
    write("sub/c.json", "{}");
    EXPECT_EQ(materialFilesIn(dir_), (std::vector<std::filesystem::path>{path("a.json"), path("b.json")}));
    EXPECT_TRUE(materialFilesIn(path("missing")).empty());
}

}  // namespace
}  // namespace patina
