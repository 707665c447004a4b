// What a prepared scene draws (scene/prepared_scene.h's sceneDraws) and what a draw's transform
// does to normals and winding (model/placement.h).
#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>

#include "model/placement.h"
#include "scene/prepared_scene.h"

namespace patina {
namespace {

TEST(Placement, NormalsGoThroughTheInverseTranspose) {
    EXPECT_EQ(normalTransform(glm::mat4(1.0f)), glm::mat3(1.0f)) << "exactly: the built-in meshes' images stay";
    // A stretch along x tilts a slanted surface's normal towards the other axes.
    const glm::mat4 stretch = glm::scale(glm::mat4(1.0f), glm::vec3(4.0f, 1.0f, 1.0f));
    const glm::vec3 n = glm::normalize(normalTransform(stretch) * glm::normalize(glm::vec3(1.0f, 1.0f, 0.0f)));
    const glm::vec3 expected = glm::normalize(glm::transpose(glm::inverse(glm::mat3(stretch))) * glm::vec3(1.0f, 1.0f, 0.0f));
    EXPECT_NEAR(glm::length(n - expected), 0.0f, 1e-6f);
    // Perpendicular to the surface after the stretch: the tangent (1, -1, 0) becomes (4, -1, 0).
    EXPECT_NEAR(glm::dot(n, glm::vec3(4.0f, -1.0f, 0.0f)), 0.0f, 1e-6f);
    // A mirror keeps the inverse transpose's sign: an outward normal stays outward.
    const glm::mat4 mirror = glm::scale(glm::mat4(1.0f), glm::vec3(-1.0f, 1.0f, 1.0f));
    EXPECT_TRUE(mirrors(mirror));
    EXPECT_FALSE(mirrors(stretch));
    EXPECT_EQ(normalTransform(mirror) * glm::vec3(1.0f, 0.0f, 0.0f), glm::vec3(-1.0f, 0.0f, 0.0f));
    // A flattened axis has no inverse; the normals still have directions, the flat one's kept.
    const glm::mat3 flat = normalTransform(glm::scale(glm::mat4(1.0f), glm::vec3(1.0f, 0.0f, 1.0f)));
    EXPECT_GT((flat * glm::vec3(0.0f, 1.0f, 0.0f)).y, 0.0f);
    EXPECT_TRUE(std::isfinite(flat[0][0]) && std::isfinite(flat[1][1]));
}

// Two primitives, two materials, three items (one with no material).
Model threeItems() {
    Model model;
    model.primitives = {makeUvSphere(4, 8), makeTorus(0.75f, 0.3f, 6, 4)};
    ModelMaterial red, blue;
    red.factors.baseColor = {0.8f, 0.1f, 0.1f};
    red.doubleSided = true;
    blue.factors.baseColor = {0.1f, 0.1f, 0.8f};
    blue.alphaMode = AlphaMode::Blend;
    blue.baseAlpha = 0.25f;
    model.materials = {red, blue};
    model.draws = {{0, 0, glm::translate(glm::mat4(1.0f), glm::vec3(-1.0f, 0.0f, 0.0f)), "left"},
                   {1, 1, glm::scale(glm::mat4(1.0f), glm::vec3(-1.0f, 1.0f, 1.0f)), "mirrored"},
                   {0, -1, glm::mat4(1.0f), "default"}};
    return model;
}

TEST(SceneDraws, ABuiltInMeshIsOneItemWithTheDocumentsMaterial) {
    Scene scene = defaultScene();
    scene.material.model = BrdfModelId::Filament;
    const PreparedScene prepared{scene, builtinMesh(MeshKind::Torus), nullptr};
    const std::vector<SceneDraw> draws = sceneDraws(prepared);
    ASSERT_EQ(draws.size(), 1u);
    EXPECT_EQ(draws[0].mesh, prepared.mesh.get());
    EXPECT_EQ(draws[0].material, MaterialParameters(scene.material));
    EXPECT_EQ(draws[0].transform, glm::mat4(1.0f));
    EXPECT_EQ(draws[0].normalTransform, glm::mat3(1.0f));
    EXPECT_TRUE(draws[0].doubleSided) << "the built-in meshes have always shown both sides";
    EXPECT_FALSE(draws[0].reverseBackNormals);
    EXPECT_FALSE(draws[0].blend);
    EXPECT_THROW(sceneDraws(PreparedScene{scene, nullptr, nullptr}), std::invalid_argument);
}

TEST(SceneDraws, AModelsItemsKeepTheirPlacesAndMaterials) {
    Scene scene = defaultScene();
    scene.material.model = BrdfModelId::Filament;
    const auto model = std::make_shared<const Model>(threeItems());
    const PreparedScene prepared{scene, builtinMesh(MeshKind::Sphere), nullptr, model};
    const std::vector<SceneDraw> draws = sceneDraws(prepared);
    ASSERT_EQ(draws.size(), 3u);
    EXPECT_EQ(draws[0].mesh, &model->primitives[0]);
    EXPECT_EQ(draws[1].mesh, &model->primitives[1]);
    EXPECT_EQ(draws[1].primitive, 1);
    EXPECT_EQ(draws[0].transform, model->draws[0].transform);
    EXPECT_EQ(draws[1].normalTransform, normalTransform(model->draws[1].transform));
    EXPECT_EQ(draws[0].material.baseColor, model->materials[0].factors.baseColor);
    EXPECT_EQ(draws[1].material.baseColor, model->materials[1].factors.baseColor);
    for (size_t i = 0; i < 2; ++i) {
        EXPECT_EQ(draws[i].material.model, model->materials[i].factors.model) << "each part its own, not the document's";
    }
    // glTF 2.0 §3.9.5: doubleSided draws both sides and lights a back face from its side.
    EXPECT_TRUE(draws[0].doubleSided && draws[0].reverseBackNormals);
    EXPECT_FALSE(draws[1].doubleSided || draws[1].reverseBackNormals);
    EXPECT_TRUE(draws[1].blend);
    EXPECT_EQ(draws[1].alpha, 0.25f);
    EXPECT_FALSE(draws[0].blend);
    EXPECT_EQ(draws[0].alpha, 1.0f) << "an opaque item's alpha is ignored (§3.9.4)";
    // §3.9.6: no material is the default one, shaded as glTF's.
    EXPECT_EQ(draws[2].material, defaultModelMaterial());
    EXPECT_EQ(defaultModelMaterial().model, BrdfModelId::Gltf);
    EXPECT_EQ(defaultModelMaterial().baseColor, glm::vec3(1.0f));
    EXPECT_EQ(defaultModelMaterial().metallic, 1.0f);
    EXPECT_EQ(defaultModelMaterial().roughness, 1.0f);
    EXPECT_EQ(defaultModelMaterial().specular, 0.5f);
    EXPECT_FALSE(draws[2].doubleSided);
}

// Scene::modelMaterials: a tuned material's factors replace the file's for every item that
// uses it, and only where the index and the name both match (a file changed since the edit
// keeps its own material).
TEST(SceneDraws, TheScenesEditOfAModelMaterialReplacesItsFactors) {
    Scene scene = defaultScene();
    Model items = threeItems();
    items.materials[0].name = "red";
    items.materials[1].name = "blue";
    const auto model = std::make_shared<const Model>(items);
    Material tuned;
    tuned.name = "red";
    tuned.baseColor = {0.2f, 0.9f, 0.3f};
    tuned.roughness = 0.15f;
    Material misnamed = tuned;
    misnamed.name = "not blue";
    scene.modelMaterials = {{0, tuned}, {1, misnamed}};
    const std::vector<SceneDraw> draws = sceneDraws(PreparedScene{scene, builtinMesh(MeshKind::Sphere), nullptr, model});
    ASSERT_EQ(draws.size(), 3u);
    EXPECT_EQ(draws[0].material.baseColor, tuned.baseColor);
    EXPECT_EQ(draws[0].material.roughness, 0.15f);
    EXPECT_EQ(draws[0].material.model, tuned.model);
    EXPECT_EQ(draws[1].material.baseColor, items.materials[1].factors.baseColor) << "another name: not this material";
    EXPECT_EQ(draws[2].material.baseColor, defaultModelMaterial().baseColor) << "no material: glTF's default";
}

// A map the scene leaves out is not drawn (the draw's maps lack it), nor exported (tunedModel);
// with every map out and no emission the item is drawn untextured.
TEST(SceneDraws, AMapTheSceneLeavesOutIsNotDrawnOrExported) {
    Scene scene = defaultScene();
    Model items = threeItems();
    items.materials[0].name = "red";
    items.materials[0].baseColor.image = 0;
    items.materials[0].normal.image = 1;
    items.images.resize(2);
    const auto model = std::make_shared<const Model>(items);
    const PreparedScene prepared{scene, builtinMesh(MeshKind::Sphere), nullptr, model};
    ASSERT_NE(sceneDraws(prepared)[0].maps, nullptr);
    EXPECT_TRUE(sceneDraws(prepared)[0].maps->normal.present());
    Material red;
    red.name = "red";
    scene.modelMaterials = {{0, red}};
    scene.modelMaterials[0].mapsOff = {"normalTexture"};
    const std::vector<SceneDraw> draws = sceneDraws(prepared);
    ASSERT_NE(draws[0].maps, nullptr);
    EXPECT_FALSE(draws[0].maps->normal.present());
    EXPECT_TRUE(draws[0].maps->baseColor.present());
    EXPECT_FALSE(tunedModel(items, scene).materials[0].normal.present());
    EXPECT_TRUE(model->materials[0].normal.present()) << "the loaded model is not touched";
    scene.modelMaterials[0].mapsOff.push_back("baseColorTexture");
    EXPECT_EQ(sceneDraws(prepared)[0].maps, nullptr);
}

TEST(SceneDraws, AMaskBelowItsCutoffHidesTheItemWhole) {
    const Scene scene = defaultScene();
    Model model = threeItems();
    model.materials[0].alphaMode = AlphaMode::Mask;
    model.materials[0].baseAlpha = 0.4f;
    model.materials[0].alphaCutoff = 0.5f;
    auto drawn = [&](const Model& m) {
        return sceneDraws(PreparedScene{scene, builtinMesh(MeshKind::Sphere), nullptr, std::make_shared<const Model>(m)});
    };
    EXPECT_EQ(drawn(model).size(), 2u);
    model.materials[0].alphaCutoff = 0.4f;   // "greater than or equal to" the cutoff: opaque
    ASSERT_EQ(drawn(model).size(), 3u);
    EXPECT_FALSE(drawn(model)[0].blend);
}

// A material named on the command line goes on every part of that name; a name the model lacks
// is refused with the model's part names, each once (2CylinderEngine repeats its names).
TEST(SceneDraws, PartMaterialsGoOnEveryPartOfTheNameAndAWrongNameListsEachOnce) {
    Model model;
    for (const char* name : {"metal", "rubber", "metal"}) {
        ModelMaterial material;
        material.name = name;
        model.materials.push_back(material);
    }
    Scene scene = defaultScene();
    Material gold = scene.material;
    gold.roughness = 0.25f;
    setPartMaterials(scene, model, gold, "metal");
    ASSERT_EQ(scene.modelMaterials.size(), 2u);
    EXPECT_EQ(scene.modelMaterials[0].index, 0);
    EXPECT_EQ(scene.modelMaterials[1].index, 2);
    EXPECT_EQ(scene.modelMaterials[1].material.roughness, 0.25f);
    try {
        setPartMaterials(scene, model, gold, "glass");
        FAIL() << "a part the model lacks was taken";
    } catch (const std::invalid_argument& error) {
        EXPECT_STREQ(error.what(), "the model has no part \"glass\" (its parts: \"metal\", \"rubber\")");
    }
}

// Each part is shaded with its own BRDF model (the file's are glTF's; an edit names its own)
// unless the scene names one for all (Scene::modelBrdf: `render --model`, a version 2 scene); a
// material put on the parts changes their factors and keeps their models.
TEST(SceneDraws, EachPartIsShadedWithItsOwnModelUnlessTheSceneNamesOne) {
    Scene scene = defaultScene();
    Model items = threeItems();
    items.materials[0].name = "red";
    items.materials[0].factors.model = BrdfModelId::Gltf;
    items.materials[1].name = "blue";
    items.materials[1].factors.model = BrdfModelId::Burley;
    const auto model = std::make_shared<const Model>(items);
    const PreparedScene prepared{scene, builtinMesh(MeshKind::Sphere), nullptr, model};
    Material blue;
    blue.name = "blue";
    blue.model = BrdfModelId::Epic;
    scene.modelMaterials = {{1, blue}};
    auto models = [&] {
        std::vector<BrdfModelId> shaded;
        for (const SceneDraw& draw : sceneDraws(PreparedScene{scene, prepared.mesh, nullptr, model})) {
            shaded.push_back(draw.material.model);
        }
        return shaded;
    };
    scene.material.model = BrdfModelId::Hammon;   // the built-in meshes': no part's
    EXPECT_EQ(models(), (std::vector{BrdfModelId::Gltf, BrdfModelId::Epic, BrdfModelId::Gltf}));
    scene.modelBrdf = BrdfModelId::Filament;
    EXPECT_EQ(models(), (std::vector{BrdfModelId::Filament, BrdfModelId::Filament, BrdfModelId::Filament}));
    scene.modelBrdf.reset();
    Material preset;
    preset.roughness = 0.9f;
    preset.model = BrdfModelId::SchlickPow5;
    setPartMaterials(scene, items, preset);
    EXPECT_EQ(models(), (std::vector{BrdfModelId::Gltf, BrdfModelId::Epic, BrdfModelId::Gltf}));
    EXPECT_EQ(sceneDraws(PreparedScene{scene, prepared.mesh, nullptr, model})[0].material.roughness, 0.9f);
}

TEST(SceneDraws, AnItemNamingWhatTheModelLacksIsRefused) {
    const Scene scene = defaultScene();
    for (const auto& [primitive, material] : {std::pair{2, 0}, std::pair{-1, 0}, std::pair{0, 2}}) {
        Model model = threeItems();
        model.draws[1].primitive = primitive;
        model.draws[1].material = material;
        const PreparedScene prepared{scene, builtinMesh(MeshKind::Sphere), nullptr, std::make_shared<const Model>(model)};
        EXPECT_THROW(sceneDraws(prepared), std::invalid_argument) << primitive << " " << material;
    }
}

}  // namespace
}  // namespace patina
