// Whether an edited scene is acceptable, by the very rules that load a preset: the scene goes
// through the preset writer and reader, so the ui refuses exactly what a file would be refused
// for, with the same messages (JSON path and rule).
#pragma once

#include "physics/model/scene.hpp"

#include <string>

namespace pl::ui {

// Every rule the scene breaks, one per line; empty when it is valid.
std::string scene_errors(const Scene& scene);

}  // namespace pl::ui
