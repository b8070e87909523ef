// Velocity arrows on the particles and the wind field on a grid, as line segments.
#pragma once

#include "app/renderer_lines.hpp"
#include "physics/stepping/experiment.hpp"

#include <optional>

namespace pl::app {

// An arrow from `from` to `to` with a two-stroke head in the plane facing `view_dir`.
void append_arrow(LineSegments& out, glm::vec3 from, glm::vec3 to, glm::vec4 color, glm::vec3 view_dir);

// Arrow length = distance covered in this time at the arrow's speed. Scaled to the room (a
// 1-2-5 step) so a few m/s read as a visible fraction of it in any room.
float velocity_arrow_time_s(const Room& room);
float wind_arrow_time_s(const Room& room);
constexpr std::size_t max_velocity_arrows_per_variant = 256;

void append_velocity_arrows(const Experiment& e, std::optional<std::size_t> only_variant, glm::vec3 view_dir,
                            LineSegments& out);
// Whose wind a pane shows: its own variant's in a split pane; overlaid, the selected variant's,
// or the first variant that has wind when the selected one has none. Empty: no wind to show.
std::optional<std::size_t> wind_variant_to_show(const Experiment& e, std::optional<std::size_t> pane_variant,
                                                std::size_t selected_variant);

// The wind of `variant` at the current time on a 6 x 4 x 6 grid filling the room.
void append_wind_arrows(const Experiment& e, std::size_t variant, glm::vec3 view_dir, LineSegments& out);

}  // namespace pl::app
