// Preset files (JSON, format "particle-lab-preset", version 1) <-> Scene.
// Loading validates everything and reports every problem with its JSON path and the rule
// broken, e.g. `particles[2].mass: must be > 0, got -1`. Unknown keys are errors.
// A failed load returns no scene, so callers keep whatever they had.
#pragma once

#include "physics/model/scene.hpp"
#include "physics/model/schema/limits.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace pl {

// Largest particle count a preset may ask for (explicit + emitted).
constexpr std::size_t max_preset_particles = schema::max_particles;

// Largest preset file load_preset reads (and save_preset writes), in bytes.
constexpr std::size_t max_preset_file_bytes = 64u << 20;

struct PresetError {
    std::string path;     // JSON path, e.g. "particles[2].mass" ("" for the whole document)
    std::string message;  // the rule broken, e.g. "must be > 0, got -1"
    std::string to_string() const { return path.empty() ? message : path + ": " + message; }
};

struct LoadResult {
    std::optional<Scene> scene;       // set only when errors is empty
    std::vector<PresetError> errors;  // every problem found, in document order
    bool over_size_limit = false;     // the file is larger than load_preset's max_bytes
    bool ok() const { return scene.has_value(); }
    std::string error_text() const;  // one error per line
};

LoadResult parse_preset(const std::string& json_text);
// Files larger than max_bytes are refused unread (the message names the limit).
LoadResult load_preset(const std::filesystem::path& file, std::size_t max_bytes = max_preset_file_bytes);

// Serialises every field (defaults included), so a saved file loads back identical.
std::string serialize_preset(const Scene& scene);

struct SaveResult {
    bool ok = false;
    std::string error;  // why it failed; the target file is untouched then
};
// Atomic: writes a uniquely named `file.tmp.XXXXXX` beside it, flushes, keeps the previous file
// as `file.bak`, renames over it. A symlink is followed: the file it leads to is replaced.
SaveResult save_preset(const std::filesystem::path& file, const Scene& scene);

}  // namespace pl
