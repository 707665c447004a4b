// docs/schema/*.schema.json describe exactly what the loaders accept: every probe the schema
// implies (tests/schema_walk.h) gets the loader's verdict the schema predicts, the schema's
// defaults are the loader's, unknown keys are written back, and every key the writers emit is
// in the schema.
#include <algorithm>
#include <functional>
#include <map>

#include <gtest/gtest.h>

#include "shading/brdf_models.h"
#include "io/scene_file.h"
#include "schema_walk.h"
#include "scratch_test.h"

namespace patina {
namespace {

using Loader = std::function<Json(const Json&, std::vector<std::string>&)>;
const std::string kSource = "probe.json";

// The loaded value written back, so that two loads compare as JSON.
Json loadMaterial(const Json& document, std::vector<std::string>& warnings) {
    return materialToJson(materialFromJson(document, "", kSource, true, warnings));
}
Json loadScene(const Json& document, std::vector<std::string>& warnings) {
    return sceneToJson(sceneFromJson(document, kSource, ".", warnings));
}

test::SchemaSet schemas() {
    return test::SchemaSet(std::filesystem::path(PATINA_SOURCE_DIR) / "docs/schema");
}

// Returns how many probes ran.
size_t checkLoaderAgainstSchema(const std::string& schemaFile, const Loader& load) {
    const test::SchemaSet set = schemas();
    const test::SchemaSet::Node root = set.root(schemaFile);
    const Json full = test::instantiate(set, root);
    std::vector<std::string> warnings;
    const Json fullLoaded = load(full, warnings);
    EXPECT_TRUE(warnings.empty()) << "every key the schema lists is known to the loader: "
                                  << (warnings.empty() ? "" : warnings[0]);
    const std::vector<test::Probe> probes = test::probes(set, root, full);
    for (const test::Probe& probe : probes) {
        SCOPED_TRACE(schemaFile + ": " + probe.description + "\n" + probe.document.dump());
        warnings.clear();
        try {
            const Json loaded = load(probe.document, warnings);
            EXPECT_TRUE(probe.accepted) << "the loader accepts what the schema refuses";
            if (probe.sameAsFull) {
                EXPECT_EQ(loaded, fullLoaded) << "a schema default differs from the loader's";
            }
            if (probe.pointer.empty()) {
                EXPECT_TRUE(warnings.empty()) << warnings[0];
            } else {
                EXPECT_EQ(warnings.size(), 1u);
                EXPECT_NE(warnings.empty() ? std::string::npos
                                           : warnings[0].find(kSource + ": " + probe.pointer +
                                                              ": unknown key"),
                          std::string::npos) << (warnings.empty() ? "" : warnings[0]);
                const Json::json_pointer unknown(probe.pointer);
                EXPECT_EQ(loaded.value(unknown, Json()), probe.document[unknown])
                    << "an unknown key is written back";
            }
        } catch (const InputError& error) {
            EXPECT_FALSE(probe.accepted) << "the loader refuses what the schema accepts: "
                                         << error.what();
            const std::string where = kSource + ": " + (probe.pointer.empty() ? "/" : probe.pointer) + ": ";
            EXPECT_EQ(std::string(error.what()).rfind(where, 0), 0u)
                << "the message names the file and the pointer: " << error.what();
        }
    }
    ::testing::Test::RecordProperty("probes", int(probes.size()));
    return probes.size();
}

TEST(SchemaSync, MaterialSchemaIsWhatTheLoaderEnforces) {
    EXPECT_GT(checkLoaderAgainstSchema("patina-material.schema.json", loadMaterial), 30u);
}

TEST(SchemaSync, SceneSchemaIsWhatTheLoaderEnforces) {
    EXPECT_GT(checkLoaderAgainstSchema("patina-scene.schema.json", loadScene), 200u);
}

TEST(SchemaSync, EveryKeyTheWritersEmitIsInTheSchema) {
    const test::SchemaSet set = schemas();
    Material material;
    material.notes = "from somewhere";
    Scene scene = defaultScene();
    scene.material = material;
    EXPECT_EQ(test::undescribedKeys(set, set.root("patina-material.schema.json"),
                                    materialToJson(material)),
              std::vector<std::string>{});
    EXPECT_EQ(test::undescribedKeys(set, set.root("patina-scene.schema.json"), sceneToJson(scene)),
              std::vector<std::string>{});
}

TEST(SchemaSync, SceneSchemaProbesGltfMeshPaths) {
    const test::SchemaSet set = schemas();
    const test::SchemaSet::Node root = set.root("patina-scene.schema.json");
    size_t taken = 0, refused = 0;
    for (const test::Probe& probe : test::probes(set, root, test::instantiate(set, root))) {
        const Json mesh = probe.document.is_object() ? probe.document.value("mesh", Json()) : Json();
        std::string text = mesh.is_string() ? mesh.get<std::string>() : "";
        std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return char(std::tolower(c)); });
        if (text.find(".gl") != std::string::npos) {
            ++(probe.accepted ? taken : refused);
        }
    }
    EXPECT_GE(taken, 4u);     // each example, in upper, lower and mixed case
    EXPECT_GE(refused, 4u);   // a letter short or over, no file name before the dot
}

// A value one anyOf branch refuses is taken when another branch takes it.
class SchemaWalk : public test::ScratchTest {};

TEST_F(SchemaWalk, AnyOfTakesWhatAnyBranchTakes) {
    write("t.schema.json", R"({"type": "object", "properties": {"v": {"default": "a", "anyOf": [
        {"enum": ["a"]}, {"type": "string", "pattern": "^a-", "examples": ["a-1"]}]}}})");
    const test::SchemaSet set(dir_);
    const test::SchemaSet::Node root = set.root("t.schema.json");
    std::map<std::string, bool> verdicts;
    for (const test::Probe& probe : test::probes(set, root, test::instantiate(set, root))) {
        if (probe.document.is_object()) {
            verdicts[probe.document.value("v", Json()).dump()] = probe.accepted;
        }
    }
    EXPECT_TRUE(verdicts.at(R"("a-other")"));   // not in the enum, but matches the pattern
    EXPECT_TRUE(verdicts.at(R"("a-1")"));
    EXPECT_FALSE(verdicts.at(R"("A-1")"));
    EXPECT_FALSE(verdicts.at("42"));
    EXPECT_FALSE(verdicts.at("{}"));
}

TEST_F(SchemaWalk, APatternNeedsAStringTypeAndExamplesItMatches) {
    for (const char* rest : {R"("type": "string")", R"("type": "string", "examples": ["b"])",
                             R"("examples": ["a"])"}) {
        write("t.schema.json", std::string(R"({"pattern": "^a", )") + rest + "}");
        const test::SchemaSet set(dir_);
        const test::SchemaSet::Node root = set.root("t.schema.json");
        EXPECT_THROW(test::probes(set, root, "a"), std::runtime_error) << rest;
    }
}

// The probes check that the loader takes every name the schema lists; this, that the schema
// lists every name the loader takes.
TEST(SchemaSync, ModelEnumIsEveryBrdfModel) {
    const test::SchemaSet set = schemas();
    const Json material = set.root("patina-material.schema.json").schema;
    std::string names;
    for (const Json& name : material["properties"]["model"]["enum"]) {
        names += (names.empty() ? "" : ", ") + name.get<std::string>();
    }
    EXPECT_EQ(names, brdfModelNames());
}

TEST(SchemaSync, SchemasAreDraft2020_12) {
    const test::SchemaSet set = schemas();
    for (const char* file : {"patina-material.schema.json", "patina-scene.schema.json"}) {
        EXPECT_EQ(set.root(file).schema.value("$schema", ""),
                  "https://json-schema.org/draft/2020-12/schema") << file;
    }
}

}  // namespace
}  // namespace patina
