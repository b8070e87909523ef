// The file dialog's listing and name check, and which presets count as shipped (read-only).
#include "ui/file_dialog.hpp"
#include "ui/lab_session.hpp"
#include "ui/sections.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <random>

namespace pl::ui {
namespace {

namespace fs = std::filesystem;

struct TempDir {
    fs::path path;
    TempDir() {
        path = fs::temp_directory_path() / ("pl_file_dialog_" + std::to_string(std::random_device{}()));
        fs::create_directories(path);
    }
    ~TempDir() {
        std::error_code ec;
        fs::remove_all(path, ec);
    }
    void touch(const std::string& name) const { std::ofstream(path / name) << "{}"; }
};

TEST(FileDialog, ListsFoldersFirstThenMatchingFilesByName) {
    TempDir t;
    t.touch("b.json");
    t.touch("a.json");
    t.touch("notes.txt");
    t.touch(".hidden.json");
    fs::create_directories(t.path / "zoo");
    fs::create_directories(t.path / "alpha");
    const std::vector<FolderEntry> e = list_folder(t.path, ".json");
    ASSERT_EQ(e.size(), 4u);
    EXPECT_EQ(e[0].name, "alpha");
    EXPECT_TRUE(e[0].is_dir);
    EXPECT_EQ(e[1].name, "zoo");
    EXPECT_EQ(e[2].name, "a.json");
    EXPECT_FALSE(e[2].is_dir);
    EXPECT_EQ(e[3].name, "b.json");
    EXPECT_EQ(list_folder(t.path, "").size(), 5u);  // every file but the hidden one
    EXPECT_TRUE(list_folder(t.path / "missing", ".json").empty());
}

TEST(FileDialog, FileNamesHaveNoSeparators) {
    EXPECT_EQ(bad_file_name("my run 2.json"), "");
    EXPECT_NE(bad_file_name(""), "");
    EXPECT_NE(bad_file_name(".."), "");
    EXPECT_NE(bad_file_name("a/b.json"), "");
    EXPECT_NE(bad_file_name(std::string(101, 'a')), "");
}

TEST(PresetFiles, ShippedPresetsAreThoseInThePresetFolder) {
    TempDir shipped, user;
    ::setenv("XDG_DATA_HOME", user.path.c_str(), 1);
    LabSession s;
    s.preset_dir = shipped.path;
    EXPECT_EQ(user_preset_dir(), user.path / "particle-lab" / "presets");
    EXPECT_TRUE(is_shipped_preset(s, shipped.path / "default.json"));
    EXPECT_FALSE(is_shipped_preset(s, user_preset_dir() / "default.json"));
    EXPECT_FALSE(is_shipped_preset(s, {}));
    // A user whose data folder is the shipped one (XDG_DATA_HOME pointing at it) owns the files.
    fs::create_directories(user_preset_dir());
    s.preset_dir = user_preset_dir();
    EXPECT_FALSE(is_shipped_preset(s, user_preset_dir() / "default.json"));
    ::unsetenv("XDG_DATA_HOME");
}

}  // namespace
}  // namespace pl::ui
