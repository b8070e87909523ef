// Helpers the preset tests share (tests/preset_io_test.cpp, tests/preset_errors_test.cpp).
#pragma once

#include "io/preset_io.hpp"

#include "temp_dir.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace pl::test {

// The shipped presets' folder.
inline const std::filesystem::path preset_dir = std::filesystem::path(PL_SOURCE_DIR) / "presets";

// A fresh folder for the files a preset test writes, removed at the end.
struct PresetTempDir : TempDir {
    PresetTempDir() : TempDir("pl_preset_") {}
};

// The whole file, byte for byte.
inline std::string read_bytes(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// A preset that must load; its errors are the test's failure message.
inline Scene load_ok(const std::filesystem::path& file) {
    LoadResult r = load_preset(file);
    EXPECT_TRUE(r.ok()) << file << ":\n" << r.error_text();
    return r.scene.value_or(Scene{});
}

}  // namespace pl::test
