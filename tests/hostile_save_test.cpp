// Saving a preset never loses the user's work: through a symlink, and with two writers at once.
#include "io/atomic_output.hpp"
#include "io/preset_io.hpp"

#include "temp_dir.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

namespace pl {
namespace {

namespace fs = std::filesystem;

const fs::path default_preset = fs::path(PL_SOURCE_DIR) / "presets" / "default.json";

std::string read_bytes(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

Scene default_scene() { return load_preset(default_preset).scene.value(); }

TEST(HostileSave, SymlinkedPresetIsSavedThroughTheLink) {
    test::TempDir dir("pl_hostile_");
    fs::create_directory(dir.path / "real");
    const fs::path target = dir.path / "real" / "preset.json";
    const fs::path link = dir.path / "link.json";
    fs::copy_file(default_preset, target);
    fs::create_symlink("real/preset.json", link);
    Scene changed = default_scene();
    changed.contact.restitution = 0.25;
    const SaveResult saved = save_preset(link, changed);
    ASSERT_TRUE(saved.ok) << saved.error;
    EXPECT_TRUE(fs::is_symlink(fs::symlink_status(link))) << "the link must stay a link";
    EXPECT_EQ(load_preset(target).scene.value().contact.restitution, 0.25) << "the target must be updated";
    EXPECT_TRUE(fs::exists(dir.path / "real" / "preset.json.bak")) << "the backup sits beside the target";
}

TEST(HostileSave, OutputThroughASymlinkReplacesTheTarget) {
    test::TempDir dir("pl_hostile_");
    const fs::path target = dir.path / "data.csv";
    std::ofstream(target) << "old\n";
    fs::create_symlink("data.csv", dir.path / "link.csv");
    AtomicOutput out(dir.path / "link.csv");
    ASSERT_TRUE(out.ok()) << out.error();
    out.stream() << "new\n";
    ASSERT_TRUE(out.commit()) << out.error();
    EXPECT_TRUE(fs::is_symlink(fs::symlink_status(dir.path / "link.csv")));
    EXPECT_EQ(read_bytes(target), "new\n");
}

// Two processes save different scenes to the same preset in a loop while the parent reads it:
// every read must be a whole, valid preset (a shared temporary name corrupted it every time).
TEST(HostileSave, ConcurrentWritersNeverLeaveACorruptPreset) {
    test::TempDir dir("pl_hostile_");
    const fs::path file = dir.path / "shared.json";
    ASSERT_TRUE(save_preset(file, default_scene()).ok);
    constexpr int saves_per_writer = 150;
    pid_t writers[2];
    for (int w = 0; w < 2; ++w) {
        writers[w] = ::fork();
        ASSERT_GE(writers[w], 0);
        if (writers[w] == 0) {
            Scene s = default_scene();
            s.contact.restitution = w == 0 ? 0.1 : 0.9;
            int failures = 0;
            for (int i = 0; i < saves_per_writer; ++i) failures += save_preset(file, s).ok ? 0 : 1;
            ::_exit(failures == 0 ? 0 : 1);
        }
    }
    int corrupt = 0, reads = 0;
    int status[2] = {0, 0};
    bool done[2] = {false, false};
    while (!done[0] || !done[1]) {
        const LoadResult r = load_preset(file);
        ++reads;
        if (!r.ok()) ++corrupt;
        for (int w = 0; w < 2; ++w)
            if (!done[w]) done[w] = ::waitpid(writers[w], &status[w], WNOHANG) == writers[w];
    }
    for (int w = 0; w < 2; ++w) EXPECT_TRUE(WIFEXITED(status[w]) && WEXITSTATUS(status[w]) == 0) << "a save failed";
    EXPECT_EQ(corrupt, 0) << corrupt << " of " << reads << " reads found a broken preset";
    EXPECT_TRUE(load_preset(file).ok());
    for (const auto& entry : fs::directory_iterator(dir.path))
        EXPECT_EQ(entry.path().filename().string().find(".tmp"), std::string::npos) << entry.path() << " left behind";
}

}  // namespace
}  // namespace pl
