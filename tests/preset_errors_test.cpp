// Preset errors and saving: every problem is reported with its JSON path and rule, broken JSON
// with its line and column, floods of errors are capped; saves are atomic and keep a backup,
// and an invalid scene is never written.
#include "io/preset_io.hpp"

#include "preset_test_support.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace pl {
namespace {

namespace fs = std::filesystem;
using TempDir = test::PresetTempDir;
using test::load_ok;
using test::preset_dir;
using test::read_bytes;

TEST(PresetErrors, EveryProblemIsReportedWithPathAndRule) {
    const LoadResult r = parse_preset(R"({ "format": "particle-lab-preset", "version": 1,
        "room": { "center": [0, 0, 0], "size": [10, 0, 10] },
        "drag": { "model": "quadratic", "cdd": 0.5 },
        "contact": { "restitution": 1.5 },
        "integrator": { "method": "rk5" },
        "particles": [ { "position": [0, 0, 0] }, { "position": [0, 0, 0] }, { "position": [0, 0, 0], "mass": -1 } ] })");
    ASSERT_FALSE(r.ok());
    EXPECT_FALSE(r.scene.has_value());
    const std::string expected =
        "room.size[1]: must be > 0, got 0\n"
        "drag.cdd: unknown key (expected one of model, cd, b, lift, spin_decay)\n"
        "contact.restitution: must be in [0, 1], got 1.5\n"
        "integrator.method: unknown value \"rk5\"; expected one of explicit_euler, semi_implicit_euler, "
        "velocity_verlet, rk4, dopri5, exponential\n"
        "particles[2].mass: must be >= 1e-15, got -1";
    EXPECT_EQ(r.error_text(), expected);
    ASSERT_EQ(r.errors.size(), 5u);
    EXPECT_EQ(r.errors[4].path, "particles[2].mass");
    EXPECT_EQ(r.errors[4].message, "must be >= 1e-15, got -1");
}

TEST(PresetErrors, ParticleThatDoesNotFitNamesItsRadiusAndPosition) {
    const LoadResult r = parse_preset(R"({ "format": "particle-lab-preset", "version": 1,
        "room": { "center": [0, 0, 0], "size": [10, 6, 10] },
        "particles": [ { "position": [4.8, 0, 0], "radius": 0.5 } ] })");
    ASSERT_EQ(r.errors.size(), 1u) << r.error_text();
    EXPECT_EQ(r.errors[0].path, "particles[0]");
    EXPECT_EQ(r.errors[0].message.rfind("sphere (radius 0.5) does not fit inside the room at position [4.8, 0, 0]", 0), 0u)
        << r.errors[0].message;
}

TEST(PresetErrors, DuplicateKeysAreErrorsWithTheirPath) {
    const LoadResult r = parse_preset(R"({ "format": "particle-lab-preset", "version": 1,
        "room": { "center": [0, 0, 0], "size": [10, 6, 10] },
        "particles": [ { "position": [0, 0, 0] }, { "position": [0, 0, 0], "mass": 1, "mass": 2 } ] })");
    ASSERT_EQ(r.errors.size(), 1u) << r.error_text();
    EXPECT_EQ(r.errors[0].to_string(), "particles[1].mass: duplicate key (each key may appear only once)");
}

TEST(PresetErrors, BrokenJsonGivesLineAndColumn) {
    const LoadResult r = parse_preset("{\n  \"format\": \"particle-lab-preset\",\n  \"version\": 1,,\n}");
    ASSERT_EQ(r.errors.size(), 1u);
    EXPECT_EQ(r.errors[0].path, "");
    EXPECT_NE(r.errors[0].message.find("line 3, column 16"), std::string::npos) << r.errors[0].message;
}

TEST(PresetErrors, AFloodOfErrorsIsCappedWithACount) {
    std::string particles;
    for (int i = 0; i < 3000; ++i) particles += std::string(i ? "," : "") + R"({ "position": [0, 0, 0], "mass": -1 })";
    const LoadResult r = parse_preset(R"({ "format": "particle-lab-preset", "version": 1,
        "room": { "center": [0, 0, 0], "size": [10, 6, 10] }, "particles": [)" + particles + "] }");
    ASSERT_FALSE(r.ok());
    ASSERT_EQ(r.errors.size(), 1001u);
    EXPECT_EQ(r.errors.back().to_string(), "... and 2000 more errors not shown");
}

// ---------------------------------------------------------------- saving

TEST(PresetSave, WritesAtomicallyAndKeepsThePreviousFileAsBackup) {
    TempDir dir;
    const fs::path file = dir.path / "mine.json";
    Scene first = load_ok(preset_dir / "default.json");
    ASSERT_TRUE(save_preset(file, first).ok);
    EXPECT_FALSE(fs::exists(dir.path / "mine.json.bak")) << "nothing to back up on the first save";
    const std::string first_bytes = read_bytes(file);

    Scene second = first;
    second.contact.restitution = 0.5;
    const SaveResult saved = save_preset(file, second);
    ASSERT_TRUE(saved.ok) << saved.error;
    EXPECT_EQ(read_bytes(dir.path / "mine.json.bak"), first_bytes);
    EXPECT_FALSE(fs::exists(dir.path / "mine.json.tmp"));
    EXPECT_EQ(load_ok(file).contact.restitution, 0.5);

    // A third save backs up the second version.
    const std::string second_bytes = read_bytes(file);
    ASSERT_TRUE(save_preset(file, first).ok);
    EXPECT_EQ(read_bytes(dir.path / "mine.json.bak"), second_bytes);
    EXPECT_EQ(read_bytes(file), first_bytes);
}

TEST(PresetSave, RefusesAnInvalidSceneAndWritesNothing) {
    TempDir dir;
    const fs::path file = dir.path / "bad.json";
    Scene s = load_ok(preset_dir / "default.json");
    s.particles[0].mass = -1;
    s.integrator.dt = std::numeric_limits<double>::quiet_NaN();
    const SaveResult r = save_preset(file, s);
    EXPECT_FALSE(r.ok);
    EXPECT_NE(r.error.find("particles[0].mass: must be >= 1e-15, got -1"), std::string::npos) << r.error;
    EXPECT_NE(r.error.find("integrator.dt"), std::string::npos) << r.error;
    EXPECT_TRUE(fs::is_empty(dir.path));
}

}  // namespace
}  // namespace pl
