// Crash recovery (autosave.h): each editor's working scene is written to a file of its own a
// while after it changes, offered back at the next start only when the editor that wrote it is
// gone, restored as a document of its own, and gone after a clean quit or a discard. One process
// stands in for several editors here: flock(2) locks taken through separate opens exclude each
// other within a process as across processes.
#include <fstream>

#include <gtest/gtest.h>

#include "storage/autosave.h"
#include "state/editor_state.h"
#include "io/json_reader.h"
#include "scratch_test.h"

namespace patina::editor {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

class AutosaveTest : public test::ScratchTest {
protected:
    fs::path folder() const { return dir_ / "config" / "autosave"; }
    std::vector<fs::path> filesIn(const std::string& extension) const {
        std::vector<fs::path> files;
        std::error_code ignored;
        for (const auto& entry : fs::directory_iterator(folder(), ignored)) {
            if (entry.path().extension() == extension) {
                files.push_back(entry.path());
            }
        }
        return files;
    }
    // An edit, held still long enough to be written.
    void editAndWrite(EditorState& session, float roughness) {
        session.scene.material.roughness = roughness;
        commitEdits(session);
        updateAutosave(session, session.autosave, session, t0);
        updateAutosave(session, session.autosave, session, t0 + kAutosaveDelay);
        t0 += 10s;
    }
    AutosaveClock::time_point t0 = AutosaveClock::now();
};

TEST_F(AutosaveTest, AChangeIsWrittenOnceItHoldsStillAndOfferedBackAtTheNextStart) {
    auto session = std::make_unique<EditorState>();
    startAutosave(*session, *session, *session, folder());
    EXPECT_FALSE(updateAutosave(*session, session->autosave, *session, t0).has_value())
        << "nothing changed, nothing to write";
    EXPECT_FALSE(fs::exists(session->autosave.file));

    session->scene.material.roughness = 0.0625f;
    session->scene.lights[0].intensity = 3.5f;
    session->scene.camera.position = {1.0f, 2.0f, 3.0f};
    commitEdits(*session);
    const auto wait = updateAutosave(*session, session->autosave, *session, t0);
    ASSERT_TRUE(wait.has_value());
    EXPECT_LE(*wait, kAutosaveDelay);
    EXPECT_TRUE(updateAutosave(*session, session->autosave, *session, t0 + 1s).has_value());
    EXPECT_FALSE(fs::exists(session->autosave.file)) << "written before the scene held still";
    EXPECT_FALSE(updateAutosave(*session, session->autosave, *session, t0 + kAutosaveDelay + 1ms).has_value());
    const fs::path written = session->autosave.file;
    ASSERT_TRUE(fs::exists(written));
    session.reset();   // killed here: its lock goes with it, its file stays

    EditorState next;
    startAutosave(next, next, next, folder());
    ASSERT_TRUE(next.recoverable.has_value()) << next.error;
    EXPECT_FALSE(next.recoverable->savedAt.empty());
    EXPECT_NE(next.autosave.file, written) << "each editor writes a file of its own";
    restoreRecoverable(next, next, next, next);
    EXPECT_EQ(next.scene.material.roughness, 0.0625f);
    EXPECT_EQ(next.scene.lights[0].intensity, 3.5f);
    EXPECT_EQ(next.scene.camera.position, glm::vec3(1.0f, 2.0f, 3.0f));
    EXPECT_TRUE(next.dirty()) << "restored work is not saved work";
    EXPECT_FALSE(next.history.canUndo()) << "the restored work is a document of its own";
    EXPECT_FALSE(fs::exists(written)) << "the work now lives in this editor's file";
    ASSERT_TRUE(fs::exists(next.autosave.file)) << "kept at once, before any other change";
    EXPECT_NE(readJsonFile(next.autosave.file).dump().find("0.0625"), std::string::npos);
}

// The issue's route: editor 1 edits and autosaves; editor 2 starts and used to offer editor
// 1's live work as "did not close normally", and its Discard deleted the one shared file; then
// editor 1 was killed and nothing was left to recover.
TEST_F(AutosaveTest, ARunningEditorsWorkIsNeitherOfferedNorDeletedByAnother) {
    auto first = std::make_unique<EditorState>();
    startAutosave(*first, *first, *first, folder());
    editAndWrite(*first, 0.3f);
    ASSERT_TRUE(fs::exists(first->autosave.file));

    EditorState second;
    startAutosave(second, second, second, folder());
    EXPECT_FALSE(second.recoverable.has_value()) << "editor 1 is running: its work is its own";
    discardRecoverable(second);
    editAndWrite(second, 0.9f);
    EXPECT_TRUE(fs::exists(first->autosave.file));
    EXPECT_EQ(filesIn(".json").size(), 2u);

    first.reset();   // killed
    EditorState third;
    startAutosave(third, third, third, folder());
    ASSERT_TRUE(third.recoverable.has_value()) << third.error;
    EXPECT_EQ(third.recoverable->scene.material.roughness, 0.3f) << "editor 1's work, not editor 2's";
    EXPECT_TRUE(third.autosave.waiting.empty()) << "editor 2 is still running";
}

TEST_F(AutosaveTest, EveryEditorThatIsGoneIsOfferedInTurn) {
    for (float roughness : {0.1f, 0.2f}) {
        EditorState session;
        startAutosave(session, session, session, folder());
        editAndWrite(session, roughness);
    }   // both gone without a clean quit
    EditorState next;
    startAutosave(next, next, next, folder());
    ASSERT_TRUE(next.recoverable.has_value());
    EXPECT_EQ(next.autosave.waiting.size(), 1u);
    // While one editor offers them, another starting does not offer them too.
    EditorState alongside;
    startAutosave(alongside, alongside, alongside, folder());
    EXPECT_FALSE(alongside.recoverable.has_value());
    discardRecoverable(next);
    ASSERT_TRUE(next.recoverable.has_value()) << "the second one next";
    discardRecoverable(next);
    EXPECT_FALSE(next.recoverable.has_value());
    EXPECT_EQ(filesIn(".json").size(), 0u) << "both discarded; this editor has written nothing yet";
}

TEST_F(AutosaveTest, ACleanQuitOrADiscardLeavesNothingToRecover) {
    EditorState session;
    startAutosave(session, session, session, folder());
    editAndWrite(session, 0.2f);
    ASSERT_TRUE(fs::exists(session.autosave.file));
    removeAutosave(session.autosave);
    EXPECT_TRUE(filesIn(".json").empty());
    EXPECT_TRUE(filesIn(".lock").empty());
    EditorState next;
    startAutosave(next, next, next, folder());
    EXPECT_FALSE(next.recoverable.has_value());
}

TEST_F(AutosaveTest, LocksOfEditorsThatWroteNothingAreTidiedButARunningOnesStays) {
    auto running = std::make_unique<EditorState>();
    startAutosave(*running, *running, *running, folder());
    {
        EditorState crashedAtStart;
        startAutosave(crashedAtStart, crashedAtStart, crashedAtStart, folder());
    }   // gone without a file of its own
    EXPECT_EQ(filesIn(".lock").size(), 2u);
    EditorState next;
    startAutosave(next, next, next, folder());
    EXPECT_EQ(filesIn(".lock").size(), 2u) << "the running editor's and this one's";
    EXPECT_TRUE(fs::exists(fs::path(running->autosave.file).replace_extension(".lock")));
}

TEST_F(AutosaveTest, TheFileEarlierVersionsSharedIsOfferedOnce) {
    EditorState old;
    old.scene.material.roughness = 0.44f;
    fs::create_directories(folder().parent_path());
    std::ofstream(folder().parent_path() / "autosave.json") << autosaveText(old);
    EditorState next;
    startAutosave(next, next, next, folder());
    ASSERT_TRUE(next.recoverable.has_value()) << next.error;
    EXPECT_EQ(next.recoverable->scene.material.roughness, 0.44f);
    EXPECT_FALSE(fs::exists(folder().parent_path() / "autosave.json"));
}

TEST_F(AutosaveTest, AnUnreadableAutosaveIsReportedAndKept) {
    fs::create_directories(folder());
    const fs::path bad = folder() / "editor-1-1.json";
    std::ofstream(bad) << R"({"format": "patina-autosave", "version": 1, "scene": {"format": "x"}})";
    EditorState next;
    startAutosave(next, next, next, folder());
    EXPECT_FALSE(next.recoverable.has_value());
    EXPECT_NE(next.error.find("could not be read"), std::string::npos) << next.error;
    EXPECT_TRUE(fs::exists(bad));
}

TEST_F(AutosaveTest, AFailedWriteIsSaidOnce) {
    EditorState session;
    startAutosave(session, session, session, folder());
    ASSERT_FALSE(session.autosave.file.empty()) << session.error;
    fs::create_directories(session.autosave.file);   // a folder where the file would go
    session.scene.material.roughness = 0.7f;
    updateAutosave(session, session.autosave, session, t0);
    updateAutosave(session, session.autosave, session, t0 + kAutosaveDelay);
    EXPECT_NE(session.error.find("Autosave failed"), std::string::npos) << session.error;
    session.error.clear();
    session.scene.material.roughness = 0.8f;
    updateAutosave(session, session.autosave, session, t0 + 10s);
    updateAutosave(session, session.autosave, session, t0 + 10s + kAutosaveDelay);
    EXPECT_TRUE(session.error.empty()) << "said once: " << session.error;
}

TEST_F(AutosaveTest, AnAutosaveFolderThatCannotBeMadeSaysAutosaveIsOff) {
    fs::create_directories(dir_ / "config");
    std::ofstream(folder()) << "a file where the folder would be";
    EditorState session;
    startAutosave(session, session, session, folder());
    EXPECT_TRUE(session.autosave.file.empty());
    EXPECT_NE(session.error.find("Autosave is off"), std::string::npos) << session.error;
    session.scene.material.roughness = 0.7f;
    EXPECT_FALSE(updateAutosave(session, session.autosave, session, t0).has_value());
}

// The restore prompt names the work: a model's by its file and how many parts were tuned.
TEST(RecoverableSummary, NamesTheMaterialOrTheModel) {
    Scene scene = defaultScene();
    scene.material.name = "gold";
    EXPECT_EQ(recoverableSummary(scene), "Material \"gold\", " + std::to_string(scene.lights.size()) + " light(s).");
    scene.meshFile = "/models/engine.glb";
    scene.modelMaterials.push_back({0, scene.material});
    EXPECT_EQ(recoverableSummary(scene),
              "Model engine.glb, 1 of its materials tuned, " + std::to_string(scene.lights.size()) + " light(s).");
}

}  // namespace
}  // namespace patina::editor
