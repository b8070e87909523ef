// Where the shipped data (presets/, shaders/) lives. No path is compiled in: the binary looks
// relative to itself first, so an installed tree can be moved to any prefix, then along the
// XDG base directory search path.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace pl::app {

// The folders searched, in order:
//   <dir of the binary>/../share/particle-lab   (installed: PREFIX/bin/particle-lab)
//   <dir of the binary>/share/particle-lab      (build tree: CMake mirrors presets/ and shaders/ there)
//   $XDG_DATA_HOME/particle-lab, then each of $XDG_DATA_DIRS/particle-lab
//   (defaults ~/.local/share and /usr/local/share:/usr/share, per the XDG base directory spec).
std::vector<std::filesystem::path> data_dir_candidates();

// The first candidate holding both presets/ and shaders/; empty when none does.
std::filesystem::path data_dir();

// data_dir()/sub, or `sub` itself (relative to the working directory) when no data folder was
// found, so that the error that follows names a path the user can check.
std::filesystem::path data_path(const std::string& sub);

}  // namespace pl::app
