// Trails as line segments that fade with age, in each particle's colour.
#pragma once

#include "app/renderer_lines.hpp"
#include "app/trail_history.hpp"
#include "ui/palette.hpp"

#include <optional>

namespace pl::app {

// Appends the trails of `only_variant` (all variants when empty). Trails of particles other
// than the first few are drawn only while they are selected.
void append_trails(const TrailHistory& history, const Experiment& experiment, std::optional<std::size_t> only_variant,
                   std::size_t selected_particle, LineSegments& out);

}  // namespace pl::app
