// Bad input never hurts: every preset in tests/bad_presets/ fails to load with the message its
// .expect sidecar names; bad files, directories and unwritable places fail clearly and lose nothing.
#include "io/preset_io.hpp"

#include "temp_dir.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/stat.h>
#include <unistd.h>

namespace pl {
namespace {

namespace fs = std::filesystem;

const fs::path catalogue_dir = fs::path(PL_SOURCE_DIR) / "tests" / "bad_presets";
const fs::path default_preset = fs::path(PL_SOURCE_DIR) / "presets" / "default.json";

struct TempDir : test::TempDir {
    TempDir() : test::TempDir("pl_bad_presets_") {}
};

std::string read_bytes(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

void write_bytes(const fs::path& file, const std::string& bytes) {
    std::ofstream out(file, std::ios::binary);
    out << bytes;
}

std::vector<std::string> expectation_lines(const fs::path& file) {
    std::vector<std::string> lines;
    std::istringstream in(read_bytes(file));
    for (std::string line; std::getline(in, line);)
        if (!line.empty()) lines.push_back(line);
    return lines;
}

// Whether a save left a temporary file (NAME.tmp.XXXXXX) behind.
bool has_temporary_files(const fs::path& dir) {
    for (const auto& entry : fs::directory_iterator(dir))
        if (entry.path().filename().string().find(".tmp") != std::string::npos) return true;
    return false;
}

bool running_as_root() { return ::geteuid() == 0; }

// Errors without a path concern the whole document (or the file), never a single field.
bool is_whole_document_error(const std::string& message) {
    for (const char* prefix : {"not valid JSON: ", "not valid UTF-8 text: ", "expected a JSON object at the top level",
                               "... and ", "cannot open preset ", "cannot read preset ", "preset "})
        if (message.rfind(prefix, 0) == 0) return true;
    return message.find(" is a directory") != std::string::npos || message.find(" is not a regular file") != std::string::npos;
}

bool is_identifier_char(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '$';
}

// A JSON path as the loader writes it: an identifier or ["quoted key"], then .identifier,
// [index] or ["quoted key"] segments (a quoted key may end in "..." when shortened).
bool looks_like_json_path(const std::string& path) {
    std::size_t i = 0;
    const auto identifier = [&] {
        const std::size_t start = i;
        if (i < path.size() && (path[i] < '0' || path[i] > '9'))
            while (i < path.size() && is_identifier_char(path[i])) ++i;
        return i > start;
    };
    const auto bracket = [&] {
        if (path[i] != '[') return false;
        ++i;
        if (i < path.size() && path[i] == '"') {
            for (++i; i < path.size() && path[i] != '"'; ++i)
                if (path[i] == '\\') ++i;
            if (i >= path.size()) return false;
            ++i;
            if (path.compare(i, 3, "...") == 0) i += 3;
        } else {
            const std::size_t start = i;
            while (i < path.size() && path[i] >= '0' && path[i] <= '9') ++i;
            if (i == start) return false;
        }
        if (i >= path.size() || path[i] != ']') return false;
        ++i;
        return true;
    };
    if (path.empty() || !(path[0] == '[' ? bracket() : identifier())) return false;
    while (i < path.size()) {
        if (path[i] == '.') {
            ++i;
            if (!identifier()) return false;
        } else if (!bracket()) {
            return false;
        }
    }
    return true;
}

void expect_well_formed(const LoadResult& r, const std::string& context) {
    EXPECT_FALSE(r.ok()) << context;
    EXPECT_FALSE(r.scene.has_value()) << context << ": a failed load returns no scene";
    ASSERT_FALSE(r.errors.empty()) << context;
    for (const PresetError& e : r.errors) {
        EXPECT_FALSE(e.message.empty()) << context;
        EXPECT_EQ(e.message.find('\n'), std::string::npos) << context << ": one error per line";
        if (e.path.empty())
            EXPECT_TRUE(is_whole_document_error(e.message)) << context << ": error without a path: " << e.message;
        else
            EXPECT_TRUE(looks_like_json_path(e.path)) << context << ": not a JSON path: " << e.path;
    }
    const std::string text = r.error_text();
    EXPECT_EQ(std::count(text.begin(), text.end(), '\n') + 1,
              static_cast<std::ptrdiff_t>(r.errors.size()))
        << context;
}

// ---------------------------------------------------------------- the catalogue

TEST(BadPresetCatalogue, EveryFileFailsWithItsExpectedMessage) {
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(catalogue_dir))
        if (entry.path().extension() == ".json") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    ASSERT_GE(files.size(), 45u);
    for (const fs::path& file : files) {
        const std::string name = file.filename().string();
        SCOPED_TRACE(name);
        fs::path expect_file = file;
        expect_file.replace_extension(".expect");
        ASSERT_TRUE(fs::exists(expect_file)) << "missing sidecar " << expect_file;
        const std::vector<std::string> expected = expectation_lines(expect_file);
        ASSERT_FALSE(expected.empty()) << expect_file << " is empty";

        const LoadResult r = load_preset(file);
        expect_well_formed(r, name);
        const std::string text = r.error_text();
        for (const std::string& line : expected)
            EXPECT_NE(text.find(line), std::string::npos) << "expected \"" << line << "\" in:\n" << text;
        // The same bytes parsed from memory give the same answer as from the file.
        EXPECT_EQ(parse_preset(read_bytes(file)).error_text(), text);
    }
}

TEST(BadPresetCatalogue, PathCheckerAcceptsPathsAndRejectsProse) {
    for (const char* good : {"room", "room.size[1]", "particles[12].mass", "variants[0].wind.kind", "room[\"centre point\"]",
                             "[\"\"]", "a[\"x\\\"y\"...]"})
        EXPECT_TRUE(looks_like_json_path(good)) << good;
    for (const char* bad : {"", "room.", "room size", "1st", "room[x]", "room[1", ".room", "room..size", "must be > 0"})
        EXPECT_FALSE(looks_like_json_path(bad)) << bad;
}

TEST(BadPresetCatalogue, EveryExpectationHasItsPreset) {
    for (const auto& entry : fs::directory_iterator(catalogue_dir))
        if (entry.path().extension() == ".expect") {
            fs::path json = entry.path();
            json.replace_extension(".json");
            EXPECT_TRUE(fs::exists(json)) << entry.path() << " has no preset";
        }
}

fs::path catalogue_file(const std::string& suffix) {
    for (const auto& entry : fs::directory_iterator(catalogue_dir)) {
        const std::string name = entry.path().filename().string();
        if (name.size() > suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0)
            return entry.path();
    }
    ADD_FAILURE() << "no catalogue file ending in " << suffix;
    return {};
}

TEST(BadPresetCatalogue, CataloguePresetsAreOneDefectAwayFromValid) {
    // Guards the catalogue itself: its base document is valid, so each file tests its own defect.
    const std::string base = read_bytes(catalogue_file("_negative_mass.json"));
    const std::string defect = R"("mass": -1)";
    const std::size_t at = base.find(defect);
    ASSERT_NE(at, std::string::npos);
    const std::string fixed = std::string(base).replace(at, defect.size(), R"("mass": 0.057)");
    const LoadResult r = parse_preset(fixed);
    EXPECT_TRUE(r.ok()) << r.error_text();
}

TEST(BadPresetCatalogue, AClumpIsRefusedOnlyWithCollisions) {
    // Balls that start inside each other cost nothing without collisions: the same clumps, emitted
    // or listed, load once no variant turns them on.
    for (const char* suffix : {"_emitter_clump_with_collisions.json", "_listed_clump_with_collisions.json",
                               "_listed_crowd_beside_outliers_with_collisions.json"}) {
        const std::string clump = read_bytes(catalogue_file(suffix));
        const std::string on = R"("enabled": true)";
        const std::size_t at = clump.find(on);
        ASSERT_NE(at, std::string::npos) << suffix;
        const LoadResult off = parse_preset(std::string(clump).replace(at, on.size(), R"("enabled": false)"));
        EXPECT_TRUE(off.ok()) << suffix << ": " << off.error_text();
        // On in the scene, off in every variant: no run collides, so it loads (the runs are the
        // variants'); with one variant that keeps the scene's collisions it is refused.
        nlohmann::json scene = nlohmann::json::parse(clump);
        scene["collisions"] = {{"enabled", true}};
        for (nlohmann::json& v : scene["variants"]) v["collisions"] = {{"enabled", false}};
        const LoadResult none_collides = parse_preset(scene.dump());
        EXPECT_TRUE(none_collides.ok()) << suffix << ": " << none_collides.error_text();
        scene["variants"][0].erase("collisions");
        EXPECT_FALSE(parse_preset(scene.dump()).ok()) << suffix << ": the first variant collides";
    }
}

// ---------------------------------------------------------------- files that are not presets

TEST(BadPresetFiles, MissingFile) {
    const LoadResult r = load_preset(catalogue_dir / "no_such_preset.json");
    expect_well_formed(r, "missing");
    EXPECT_NE(r.error_text().find("no_such_preset.json"), std::string::npos) << r.error_text();
    EXPECT_NE(r.error_text().find("no such file"), std::string::npos) << r.error_text();
}

TEST(BadPresetFiles, DirectoryInsteadOfAPreset) {
    const LoadResult r = load_preset(catalogue_dir);
    expect_well_formed(r, "directory");
    EXPECT_NE(r.error_text().find("is a directory, not a preset file"), std::string::npos) << r.error_text();
    EXPECT_NE(r.error_text().find("bad_presets"), std::string::npos);
}

TEST(BadPresetFiles, DeviceInsteadOfAPreset) {
    const LoadResult r = load_preset("/dev/zero");  // endless: must not be read
    expect_well_formed(r, "device");
    EXPECT_NE(r.error_text().find("'/dev/zero' is not a regular file"), std::string::npos) << r.error_text();
}

TEST(BadPresetFiles, UnreadableFile) {
    if (running_as_root()) GTEST_SKIP() << "root can read any file";
    TempDir dir;
    const fs::path file = dir.path / "secret.json";
    fs::copy_file(default_preset, file);
    fs::permissions(file, fs::perms::none);
    const LoadResult r = load_preset(file);
    expect_well_formed(r, "unreadable");
    EXPECT_NE(r.error_text().find("cannot open preset"), std::string::npos) << r.error_text();
    EXPECT_NE(r.error_text().find("secret.json"), std::string::npos);
    EXPECT_NE(r.error_text().find("Permission denied"), std::string::npos) << r.error_text();
}

TEST(BadPresetFiles, TooLargeFileIsNotRead) {
    TempDir dir;
    const fs::path file = dir.path / "huge.json";
    write_bytes(file, "{");
    fs::resize_file(file, max_preset_file_bytes + 1);  // sparse: no disk space used
    const LoadResult r = load_preset(file);
    expect_well_formed(r, "too large");
    EXPECT_NE(r.error_text().find("is too large (67108865 bytes; the preset size limit is 67108864 bytes)"), std::string::npos)
        << r.error_text();
}

TEST(BadPresetFiles, EmptyFileIsBrokenJson) {
    TempDir dir;
    const fs::path file = dir.path / "empty.json";
    write_bytes(file, "");
    const LoadResult r = load_preset(file);
    expect_well_formed(r, "empty");
    EXPECT_EQ(r.error_text().rfind("not valid JSON: ", 0), 0u) << r.error_text();
}

// ---------------------------------------------------------------- saving that must fail safely

// Saves over an existing good preset in a way that cannot work; the old file must stay byte-identical.
struct SaveOverExisting {
    TempDir dir;
    fs::path file = dir.path / "keep.json";
    std::string original;
    Scene changed;

    SaveOverExisting() {
        fs::copy_file(default_preset, file);
        original = read_bytes(file);
        changed = load_preset(file).scene.value();
        changed.contact.restitution = 0.3;
    }

    void expect_failure_keeps_file(const std::string& reason_fragment) {
        const SaveResult r = save_preset(file, changed);
        EXPECT_FALSE(r.ok);
        EXPECT_NE(r.error.find("keep.json"), std::string::npos) << r.error;
        EXPECT_NE(r.error.find(reason_fragment), std::string::npos) << r.error;
        EXPECT_NE(r.error.find("the existing file is unchanged"), std::string::npos) << r.error;
        EXPECT_EQ(read_bytes(file), original);
    }
};

TEST(BadPresetSave, UnwritableDirectoryFailsAndKeepsTheFile) {
    if (running_as_root()) GTEST_SKIP() << "root may write into any directory; see the tests below";
    SaveOverExisting s;
    fs::permissions(s.dir.path, fs::perms::owner_read | fs::perms::owner_exec);
    s.expect_failure_keeps_file("Permission denied");
    fs::permissions(s.dir.path, fs::perms::owner_all);
    EXPECT_FALSE(has_temporary_files(s.dir.path));
}

TEST(BadPresetSave, TemporaryFileBlockedFailsAndKeepsTheFile) {
    // A 250-character name is a valid file, but its temporary sibling's name is too long.
    TempDir dir;
    const fs::path file = dir.path / (std::string(245, 'k') + ".json");
    fs::copy_file(default_preset, file);
    const std::string original = read_bytes(file);
    Scene changed = load_preset(file).scene.value();
    changed.contact.restitution = 0.3;
    const SaveResult r = save_preset(file, changed);
    EXPECT_FALSE(r.ok);
    EXPECT_NE(r.error.find("cannot create a temporary file beside it: File name too long"), std::string::npos) << r.error;
    EXPECT_NE(r.error.find("the existing file is unchanged"), std::string::npos) << r.error;
    EXPECT_EQ(read_bytes(file), original);
}

TEST(BadPresetSave, BackupBlockedFailsKeepsTheFileAndRemovesTheTemporary) {
    SaveOverExisting s;
    fs::create_directories(s.dir.path / "keep.json.bak" / "occupied");
    s.expect_failure_keeps_file("cannot keep the previous file as");
    EXPECT_FALSE(has_temporary_files(s.dir.path));
}

TEST(BadPresetSave, MissingDirectoryFailsClearly) {
    TempDir dir;
    const SaveResult r = save_preset(dir.path / "no" / "such" / "dir" / "p.json", load_preset(default_preset).scene.value());
    EXPECT_FALSE(r.ok);
    EXPECT_NE(r.error.find("No such file or directory"), std::string::npos) << r.error;
    EXPECT_TRUE(fs::is_empty(dir.path));
}

TEST(BadPresetSave, ParentIsAFileFailsClearly) {
    TempDir dir;
    write_bytes(dir.path / "plain", "not a directory");
    const SaveResult r = save_preset(dir.path / "plain" / "p.json", load_preset(default_preset).scene.value());
    EXPECT_FALSE(r.ok);
    EXPECT_NE(r.error.find("Not a directory"), std::string::npos) << r.error;
    EXPECT_EQ(read_bytes(dir.path / "plain"), "not a directory");
}

TEST(BadPresetSave, DirectoryAsTargetFailsClearly) {
    TempDir dir;
    fs::create_directory(dir.path / "p.json");
    const SaveResult r = save_preset(dir.path / "p.json", load_preset(default_preset).scene.value());
    EXPECT_FALSE(r.ok);
    EXPECT_NE(r.error.find("it is a directory"), std::string::npos) << r.error;
    EXPECT_TRUE(fs::is_empty(dir.path / "p.json"));
}

}  // namespace
}  // namespace pl
