// saveMaterialFile: atomic, keeps the previous version as NAME.json.bak, and a save that fails
// or is killed half way leaves complete files behind.
#include <algorithm>
#include <csignal>
#include <cstdio>
#include <optional>
#include <random>

#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "scratch_test.h"
#include "io/scene_file.h"

namespace patina {
namespace {

namespace fs = std::filesystem;

class MaterialSave : public test::ScratchTest {
protected:
    static Material material(float roughness, size_t noteLength = 0) {
        Material m;
        m.name = "gold";
        m.roughness = roughness;
        m.notes = std::string(noteLength, 'n');
        return m;
    }

    // The file as a material, or nullopt when it is missing, partial or not a material.
    std::optional<Material> load(const fs::path& file) const {
        std::vector<std::string> warnings;
        try {
            return loadMaterialFile(file, warnings);
        } catch (const InputError&) {
            return std::nullopt;
        }
    }

    std::vector<std::string> entries() const {
        std::vector<std::string> names;
        for (const auto& entry : fs::directory_iterator(dir_)) {
            names.push_back(entry.path().filename().string());
        }
        std::sort(names.begin(), names.end());
        return names;
    }
};

TEST_F(MaterialSave, KeepsThePreviousVersionAsBak) {
    const fs::path file = path("gold.json");
    saveMaterialFile(file, material(0.1f));
    EXPECT_FALSE(fs::exists(path("gold.json.bak"))) << "nothing to keep on the first save";
    const std::string first = read("gold.json");
    saveMaterialFile(file, material(0.2f));
    EXPECT_EQ(read("gold.json.bak"), first);
    EXPECT_EQ(load(file), material(0.2f));
    saveMaterialFile(file, material(0.3f));
    EXPECT_EQ(load(path("gold.json.bak")), material(0.2f));
    EXPECT_EQ(entries(), (std::vector<std::string>{"gold.json", "gold.json.bak"}));
}

TEST_F(MaterialSave, AnUnwritableFolderFailsWithAMessageAndKeepsTheOldFile) {
    if (geteuid() == 0) {
        // Root writes into read-only folders; a parent that is a regular file stops root too.
        write("plain", "not a folder");
        try {
            saveMaterialFile(path("plain") / "gold.json", material(0.5f));
            ADD_FAILURE() << "saving under a regular file must fail";
        } catch (const std::runtime_error& error) {
            EXPECT_NE(std::string(error.what()).find("plain/gold.json"), std::string::npos)
                << error.what();
        }
        EXPECT_EQ(read("plain"), "not a folder");
        return;
    }
    fs::create_directory(path("locked"));
    const fs::path file = path("locked") / "gold.json";
    saveMaterialFile(file, material(0.1f));
    const std::string before = read("locked/gold.json");
    fs::permissions(path("locked"), fs::perms::owner_read | fs::perms::owner_exec);
    try {
        saveMaterialFile(file, material(0.9f));
        ADD_FAILURE() << "saving into a read-only folder must fail";
    } catch (const std::runtime_error& error) {
        EXPECT_NE(std::string(error.what()).find("locked/gold.json"), std::string::npos)
            << error.what();
    }
    fs::permissions(path("locked"), fs::perms::owner_all);
    EXPECT_EQ(read("locked/gold.json"), before);
    EXPECT_EQ(std::distance(fs::directory_iterator(path("locked")), fs::directory_iterator()), 1);
}

// A folder that is not there is what the message says, with the system's code kept (ENOENT)
// for the editor's own wording.
TEST_F(MaterialSave, AMissingFolderIsSaidToBeMissing) {
    const fs::path file = path("gone") / "gold.json";
    try {
        saveMaterialFile(file, material(0.5f));
        ADD_FAILURE() << "saving into a missing folder must fail";
    } catch (const std::system_error& error) {
        EXPECT_EQ(error.code().value(), ENOENT);
        EXPECT_NE(std::string(error.what()).find("the folder '" + path("gone").string() + "' does not exist"),
                  std::string::npos)
            << error.what();
    }
    EXPECT_FALSE(fs::exists(path("gone")));
}

TEST_F(MaterialSave, AFullDiskFailsWithAMessageAndKeepsTheOldFile) {
    // RLIMIT_FSIZE makes writes past 4 KiB fail with EFBIG, as a full disk fails them with
    // ENOSPC, for root too. The child reports what it caught through a pipe.
    const fs::path file = path("gold.json");
    saveMaterialFile(file, material(0.1f));
    const std::string before = read("gold.json");
    int pipeEnds[2];
    ASSERT_EQ(pipe(pipeEnds), 0);
    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        std::signal(SIGXFSZ, SIG_IGN);
        const rlimit limit{4096, 4096};
        setrlimit(RLIMIT_FSIZE, &limit);
        std::string message = "no error";
        try {
            saveMaterialFile(file, material(0.9f, 20000));
        } catch (const std::runtime_error& error) {
            message = error.what();
        }
        (void)!::write(pipeEnds[1], message.data(), message.size());
        _exit(0);
    }
    close(pipeEnds[1]);
    std::string message;
    char buffer[256];
    for (ssize_t n; (n = ::read(pipeEnds[0], buffer, sizeof buffer)) > 0;) {
        message.append(buffer, size_t(n));
    }
    close(pipeEnds[0]);
    int status = 0;
    waitpid(child, &status, 0);
    EXPECT_NE(message.find("'" + file.string() + "'"), std::string::npos) << message;
    EXPECT_EQ(read("gold.json"), before);
    EXPECT_EQ(read("gold.json.bak"), before);
    EXPECT_EQ(entries(), (std::vector<std::string>{"gold.json", "gold.json.bak"}))
        << "no temporary file is left behind";
}

TEST_F(MaterialSave, KillingASaveAtAnyMomentLeavesCompleteFiles) {
    // Two versions of different lengths, large enough that a write takes a while: a partial
    // file fails to parse or matches neither.
    const Material a = material(0.25f, 100000), b = material(0.75f, 300000);
    const fs::path file = path("gold.json");
    saveMaterialFile(file, a);
    saveMaterialFile(file, a);   // a .bak from the start
    std::mt19937 random(5);
    std::uniform_int_distribution<int> delayMicroseconds(0, 4000);
    int killedMidWrite = 0;
    for (int kill = 0; kill < 200; ++kill) {
        const pid_t child = fork();
        ASSERT_GE(child, 0);
        if (child == 0) {
            alarm(20);   // never outlive the test
            try {
                for (int i = 0;; ++i) {
                    saveMaterialFile(file, i % 2 ? b : a);
                }
            } catch (const std::exception& error) {
                std::fprintf(stderr, "save failed: %s\n", error.what());
                _exit(3);
            }
        }
        usleep(useconds_t(delayMicroseconds(random)));
        ::kill(child, SIGKILL);
        int status = 0;
        waitpid(child, &status, 0);
        ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL)
            << "the saving child ended by itself: exit " << WEXITSTATUS(status) << ", signal "
            << (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
        const std::optional<Material> saved = load(file), backup = load(path("gold.json.bak"));
        ASSERT_TRUE(saved == a || saved == b) << "after kill " << kill << ": " << file;
        ASSERT_TRUE(backup == a || backup == b) << "after kill " << kill << ": gold.json.bak";
        // A killed save leaves its temporary file; count them as proof the kills hit writes.
        for (const std::string& name : entries()) {
            if (name.starts_with(".gold.json")) {
                ++killedMidWrite;
                fs::remove(path(name));
            }
        }
    }
    RecordProperty("kills_during_a_write", killedMidWrite);
}

}  // namespace
}  // namespace patina
