// Trails as line segments that fade with age, in each particle's colour.
#pragma once

#include "app/renderer_lines.hpp"
#include "app/trail_history.hpp"
#include "ui/palette.hpp"
#include "ui/pinned_runs.hpp"

#include <optional>

namespace pl::app {

// Appends the trails of `only_variant` (all variants when empty). Trails of particles other
// than the first `per_variant` are drawn only while they are selected.
void append_trails(const TrailHistory& history, const Experiment& experiment, std::optional<std::size_t> only_variant,
                   std::size_t selected_particle, std::size_t per_variant, LineSegments& out);

// A drop line from each of those particles in flight down to the floor, so a ball in the air
// never looks as if it lay on the floor further back.
void append_drop_lines(const Experiment& experiment, std::optional<std::size_t> only_variant, std::size_t selected_particle,
                       std::size_t per_variant, LineSegments& out);

// Appends the pinned runs' paths: faint lines in each pin's colour (the ghosts of earlier runs).
void append_pinned_paths(const ui::PinBoard& board, LineSegments& out);

}  // namespace pl::app
