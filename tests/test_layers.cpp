// The engine's layers (engine/CMakeLists.txt, docs/ARCHITECTURE.md): each folder is a library
// that may include only itself and the layers it declares, directly or through them. The linker
// enforces the libraries; this enforces the headers, which a linker never sees.
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace patina {
namespace {

namespace fs = std::filesystem;
using Layers = std::map<std::string, std::set<std::string>>;   // layer -> what it declares

// engine_layers.txt: "name: dependency ..." a line, as engine/CMakeLists.txt writes it.
Layers readLayers(const fs::path& file) {
    Layers layers;
    std::ifstream in(file);
    std::string line;
    while (std::getline(in, line)) {
        const size_t colon = line.find(':');
        if (colon == std::string::npos) {
            continue;
        }
        std::istringstream dependencies(line.substr(colon + 1));
        std::set<std::string>& declared = layers[line.substr(0, colon)];
        for (std::string dependency; dependencies >> dependency;) {
            declared.insert(dependency);
        }
    }
    return layers;
}

// Every layer `layer` may include: itself and all it reaches through declared dependencies.
std::set<std::string> reachable(const Layers& layers, const std::string& layer) {
    std::set<std::string> seen{layer};
    std::vector<std::string> open{layer};
    while (!open.empty()) {
        const std::string next = open.back();
        open.pop_back();
        if (const auto found = layers.find(next); found != layers.end()) {
            for (const std::string& dependency : found->second) {
                if (seen.insert(dependency).second) {
                    open.push_back(dependency);
                }
            }
        }
    }
    return seen;
}

// What is wrong with the includes of `text`, a file of `layer`: an include of a layer it does
// not reach, of a folder that is no layer, by a relative path, or of a windowing library.
std::vector<std::string> includeViolations(const Layers& layers, const std::string& layer, const std::string& file,
                                           const std::string& text) {
    static const std::regex include(R"(^\s*#\s*include\s*([<"])([^">]+)[">])");
    const std::set<std::string> allowed = reachable(layers, layer);
    std::vector<std::string> violations;
    std::istringstream lines(text);
    int number = 0;
    for (std::string line; std::getline(lines, line);) {
        ++number;
        std::smatch match;
        if (!std::regex_search(line, match, include)) {
            continue;
        }
        const std::string path = match[2];
        const std::string where = file + ":" + std::to_string(number) + ": ";
        if (match[1] == "<") {
            if (path.starts_with("imgui") || path.starts_with("GLFW/")) {
                violations.push_back(where + "the engine knows nothing of ImGui or GLFW: " + path);
            }
            continue;
        }
        if (path.ends_with(".glsl")) {
            continue;   // shaders/shared, the GLSL that also compiles as C++
        }
        const size_t slash = path.find('/');
        const std::string folder = slash == std::string::npos ? "" : path.substr(0, slash);
        if (folder.empty() || folder == "." || folder == "..") {
            violations.push_back(where + "includes \"" + path + "\": name the layer's folder, from engine/");
        } else if (!layers.count(folder)) {
            violations.push_back(where + "includes \"" + path + "\" from " + folder + "/, which is no engine layer");
        } else if (!allowed.count(folder)) {
            violations.push_back(where + layer + " includes \"" + path + "\" but does not depend on " + folder);
        }
    }
    return violations;
}

TEST(Layers, TheCheckFindsAnUpwardIncludeAndAcceptsADeclaredOne) {
    const Layers layers{{"shading", {}}, {"scene", {"shading"}}, {"gl", {"scene"}}};
    EXPECT_TRUE(includeViolations(layers, "gl", "gl/a.cpp", "#include \"shading/b.h\"\n#include <vector>\n").empty())
        << "through scene";
    const std::vector<std::string> upward = includeViolations(layers, "scene", "scene/a.cpp", "\n#include \"gl/r.h\"\n");
    ASSERT_EQ(upward.size(), 1u);
    EXPECT_NE(upward[0].find("scene/a.cpp:2: scene includes \"gl/r.h\""), std::string::npos) << upward[0];
    EXPECT_EQ(includeViolations(layers, "gl", "gl/a.cpp", "#include \"../scene/s.h\"\n").size(), 1u);
    EXPECT_EQ(includeViolations(layers, "gl", "gl/a.cpp", "#include \"renderer.h\"\n").size(), 1u);
    EXPECT_EQ(includeViolations(layers, "gl", "gl/a.cpp", "#include \"bench/timing.h\"\n").size(), 1u);
    EXPECT_EQ(includeViolations(layers, "gl", "gl/a.cpp", "#include <imgui.h>\n").size(), 1u);
}

TEST(Layers, NoEngineFileIncludesALayerItDoesNotDependOn) {
    const fs::path engine = fs::path(PATINA_SOURCE_DIR) / "engine";
    const Layers layers = readLayers(PATINA_LAYERS_FILE);
    ASSERT_GE(layers.size(), 8u) << PATINA_LAYERS_FILE;
    std::vector<std::string> violations;
    size_t files = 0;
    for (const auto& entry : fs::directory_iterator(engine)) {
        const std::string name = entry.path().filename().string();
        if (!entry.is_directory()) {
            EXPECT_EQ(name, "CMakeLists.txt") << "engine/ holds folders, not loose files";
            continue;
        }
        EXPECT_TRUE(layers.count(name)) << "engine/" << name << " is not declared as a layer";
        for (const auto& source : fs::recursive_directory_iterator(entry.path())) {
            const std::string extension = source.path().extension().string();
            if (extension != ".h" && extension != ".cpp") {
                continue;
            }
            std::ifstream in(source.path());
            std::stringstream text;
            text << in.rdbuf();
            ++files;
            for (std::string& violation :
                 includeViolations(layers, name, fs::relative(source.path(), engine).string(), text.str())) {
                violations.push_back(std::move(violation));
            }
        }
    }
    EXPECT_GT(files, 80u);
    for (const std::string& violation : violations) {
        ADD_FAILURE() << violation;
    }
}

// The folders say what ships and what measures (docs/ARCHITECTURE.md, "The rooms"): no layer of
// the product reaches the ground truth or the measurements, so neither is on the path from a
// file to an image.
TEST(Layers, NoProductLayerReachesTheMeasurements) {
    const Layers layers = readLayers(PATINA_LAYERS_FILE);
    const std::set<std::string> measurement{"reference", "accuracy"};
    for (const std::string& name : measurement) {
        EXPECT_TRUE(layers.count(name)) << name << " is not declared as a layer";
    }
    for (const auto& [layer, declared] : layers) {
        if (measurement.count(layer)) {
            continue;
        }
        for (const std::string& reached : reachable(layers, layer)) {
            EXPECT_FALSE(measurement.count(reached)) << layer << " reaches " << reached;
        }
    }
}

// Pixels stand on common alone (docs/ARCHITECTURE.md, image; issue 34): a PNG, a caption or a
// chart needs nothing of a scene, and the renderer, which makes an image, needs no files layer
// above it. Pictures of a scene are picture/'s.
TEST(Layers, PixelsStandOnCommonAlone) {
    const Layers layers = readLayers(PATINA_LAYERS_FILE);
    ASSERT_TRUE(layers.count("image"));
    for (const std::string& reached : reachable(layers, "image")) {
        EXPECT_TRUE(reached == "image" || reached == "common") << "image reaches " << reached;
    }
    for (const char* writer : {"io", "image", "picture"}) {   // gl reaches itself and what it declares
        EXPECT_FALSE(reachable(layers, "gl").count(writer)) << "gl reaches " << writer;
    }
}

// The editor's library takes nothing from the benchmarks.
TEST(Layers, TheEditorIncludesNoBenchmarkCode) {
    const fs::path editor = fs::path(PATINA_SOURCE_DIR) / "app" / "editor";
    const std::regex bench(R"(^\s*#\s*include\s*"bench/)");
    for (const auto& source : fs::recursive_directory_iterator(editor)) {   // panels/ too
        if (!source.is_regular_file()) {
            continue;
        }
        std::ifstream in(source.path());
        int number = 0;
        for (std::string line; std::getline(in, line);) {
            ++number;
            EXPECT_FALSE(std::regex_search(line, bench)) << source.path().filename() << ":" << number << ": " << line;
        }
    }
}

// The editor's rooms: what it holds and acts on (state/), reads and writes (storage/) and
// computes for the panels to show (views/) draw nothing, so the tests drive them without a
// window; ImGui, GLFW and GL calls live in window/ and panels/, which they never include. No file
// lies loose in app/editor/.
TEST(Layers, TheEditorsStateStorageAndViewsDrawNothing) {
    const fs::path editor = fs::path(PATINA_SOURCE_DIR) / "app" / "editor";
    for (const auto& entry : fs::directory_iterator(editor)) {
        EXPECT_TRUE(entry.is_directory()) << entry.path().filename() << " lies outside the editor's rooms";
    }
    const std::regex drawing(R"(^\s*#\s*include\s*[<"](imgui|GLFW/|epoxy/|window/|panels/))");
    int checked = 0;
    for (const char* room : {"state", "storage", "views"}) {
        for (const auto& source : fs::recursive_directory_iterator(editor / room)) {
            if (!source.is_regular_file()) {
                continue;
            }
            ++checked;
            std::ifstream in(source.path());
            int number = 0;
            for (std::string line; std::getline(in, line);) {
                ++number;
                EXPECT_FALSE(std::regex_search(line, drawing))
                    << room << "/" << source.path().filename().string() << ":" << number << ": " << line;
            }
        }
    }
    EXPECT_GT(checked, 30) << "the rooms are missing or moved";
}
}  // namespace
}  // namespace patina
