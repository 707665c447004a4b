// Crash recovery (autosave.h): the working scene is written a while after it changes, offered
// back at the next start, restored as one undo step, and gone after a clean quit or a discard.
#include <fstream>

#include <gtest/gtest.h>

#include "autosave.h"
#include "editor_state.h"
#include "scratch_test.h"

namespace patina::editor {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

class AutosaveTest : public test::ScratchTest {
protected:
    fs::path file() const { return dir_ / "config" / "autosave.json"; }
    const AutosaveClock::time_point t0 = AutosaveClock::now();
};

TEST_F(AutosaveTest, AChangeIsWrittenOnceItHoldsStillAndOfferedBackAtTheNextStart) {
    EditorState session;
    startAutosave(session, file());
    EXPECT_FALSE(updateAutosave(session, t0).has_value()) << "nothing changed, nothing to write";
    EXPECT_FALSE(fs::exists(file()));

    session.scene.material.roughness = 0.0625f;
    session.scene.lights[0].intensity = 3.5f;
    session.scene.camera.position = {1.0f, 2.0f, 3.0f};
    commitEdits(session);
    const auto wait = updateAutosave(session, t0);
    ASSERT_TRUE(wait.has_value());
    EXPECT_LE(*wait, kAutosaveDelay);
    EXPECT_TRUE(updateAutosave(session, t0 + 1s).has_value());
    EXPECT_FALSE(fs::exists(file())) << "written before the scene held still";
    EXPECT_FALSE(updateAutosave(session, t0 + kAutosaveDelay + 1ms).has_value());
    ASSERT_TRUE(fs::exists(file()));
    // Killed here: the next start finds it.
    EditorState next;
    const Material before = next.scene.material;
    startAutosave(next, file());
    ASSERT_TRUE(next.recoverable.has_value()) << next.error;
    EXPECT_FALSE(next.recoverable->savedAt.empty());
    // While offered, nothing overwrites the file.
    next.scene.material.metallic = 1.0f;
    EXPECT_FALSE(updateAutosave(next, t0 + 10s).has_value());
    next.scene.material.metallic = 0.0f;
    restoreRecoverable(next);
    EXPECT_EQ(next.scene.material.roughness, 0.0625f);
    EXPECT_EQ(next.scene.lights[0].intensity, 3.5f);
    EXPECT_EQ(next.scene.camera.position, glm::vec3(1.0f, 2.0f, 3.0f));
    EXPECT_TRUE(next.dirty()) << "restored work is not saved work";
    undo(next);
    EXPECT_EQ(next.scene.material, before) << "the restore is one undo step";
}

TEST_F(AutosaveTest, ACleanQuitOrADiscardLeavesNothingToRecover) {
    EditorState session;
    startAutosave(session, file());
    session.scene.material.roughness = 0.2f;
    updateAutosave(session, t0);
    updateAutosave(session, t0 + kAutosaveDelay);
    ASSERT_TRUE(fs::exists(file()));
    removeAutosave(session);
    EditorState next;
    startAutosave(next, file());
    EXPECT_FALSE(next.recoverable.has_value());

    session.scene.material.roughness = 0.3f;
    updateAutosave(session, t0 + 5s);
    updateAutosave(session, t0 + 5s + kAutosaveDelay);
    EditorState third;
    startAutosave(third, file());
    ASSERT_TRUE(third.recoverable.has_value());
    discardRecoverable(third);
    EXPECT_FALSE(fs::exists(file()));
    EXPECT_NE(third.scene.material.roughness, 0.3f);
}

TEST_F(AutosaveTest, AnUnreadableAutosaveIsReportedAndKept) {
    fs::create_directories(file().parent_path());
    std::ofstream(file()) << R"({"format": "patina-autosave", "version": 1, "scene": {"format": "x"}})";
    EditorState next;
    startAutosave(next, file());
    EXPECT_FALSE(next.recoverable.has_value());
    EXPECT_NE(next.error.find("autosave could not be read"), std::string::npos) << next.error;
    EXPECT_TRUE(fs::exists(file()));
}

TEST_F(AutosaveTest, AFailedWriteIsSaidOnce) {
    fs::create_directories(dir_ / "blocked");
    EditorState session;
    startAutosave(session, dir_ / "blocked" / "autosave.json" / "inside-a-file");
    std::ofstream(dir_ / "blocked" / "autosave.json") << "a file where a folder would be";
    session.scene.material.roughness = 0.7f;
    updateAutosave(session, t0);
    updateAutosave(session, t0 + kAutosaveDelay);
    EXPECT_NE(session.error.find("Autosave failed"), std::string::npos) << session.error;
    session.error.clear();
    session.scene.material.roughness = 0.8f;
    updateAutosave(session, t0 + 10s);
    updateAutosave(session, t0 + 10s + kAutosaveDelay);
    EXPECT_TRUE(session.error.empty()) << "said again: " << session.error;
}

}  // namespace
}  // namespace patina::editor
