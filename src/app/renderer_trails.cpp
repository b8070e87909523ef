#include "app/renderer_trails.hpp"

#include <cmath>

namespace pl::app {

void append_trails(const TrailHistory& history, const Experiment& e, std::optional<std::size_t> only_variant,
                   std::size_t selected_particle, std::size_t per_variant, LineSegments& out) {
    const std::size_t variants = e.variant_count();
    for (const Trail& trail : history.trails()) {
        if (only_variant && trail.variant != *only_variant) continue;
        if (trail.variant >= variants || trail.particle >= e.run(trail.variant).particle_count()) continue;
        if (trail.particle >= per_variant && trail.particle != selected_particle) continue;
        if (trail.count < 2) continue;
        const ui::Rgb rgb = ui::series_color(variants, trail.variant, trail.particle);
        auto color = [&](std::size_t k) {
            // Fades over the ring's full length (a fixed span of simulated time), so a young
            // trail is drawn strong throughout and an old one melts into the room.
            const float age = static_cast<float>(trail.count - 1 - k) / static_cast<float>(TrailHistory::capacity);
            const float alpha = 0.9f * std::pow(1.0f - age, 1.5f);
            return glm::vec4(rgb.r, rgb.g, rgb.b, alpha);
        };
        for (std::size_t k = 0; k + 1 < trail.count; ++k)
            add_segment(out, trail.at(k), trail.at(k + 1), color(k), color(k + 1));
        // Close the gap between the last sample and where the particle is now.
        const glm::vec3 now(e.run(trail.variant).state().position(trail.particle));
        const glm::vec4 c = color(trail.count - 1);
        add_segment(out, trail.at(trail.count - 1), now, c, c);
    }
}

void append_drop_lines(const Experiment& e, std::optional<std::size_t> only_variant, std::size_t selected_particle,
                       std::size_t per_variant, LineSegments& out) {
    const std::size_t variants = e.variant_count();
    for (std::size_t v = 0; v < variants; ++v) {
        if (only_variant && v != *only_variant) continue;
        const ParticleState& s = e.run(v).state();
        const double floor_y = e.run(v).model().room.floor_y();
        auto drop = [&](std::size_t i) {
            // A particle resting on (or within a millimetre of) the floor needs no line.
            if (s.y[i] - s.radius[i] - floor_y < 1e-3) return;
            const ui::Rgb rgb = ui::series_color(variants, v, i);
            const glm::vec4 colour(rgb.r, rgb.g, rgb.b, 0.35f);
            const glm::vec3 bottom(static_cast<float>(s.x[i]), static_cast<float>(s.y[i] - s.radius[i]), static_cast<float>(s.z[i]));
            add_segment(out, bottom, {bottom.x, static_cast<float>(floor_y), bottom.z}, colour, colour);
        };
        const std::size_t shown = std::min(s.size(), per_variant);
        for (std::size_t i = 0; i < shown; ++i) drop(i);
        if (selected_particle >= shown && selected_particle < s.size()) drop(selected_particle);
    }
}

void append_pinned_paths(const ui::PinBoard& board, LineSegments& out) {
    for (const ui::PinnedRun& run : board.runs) {
        const ui::Rgba c = ui::pin_color(run.number, 0.5f);
        const glm::vec4 colour(c[0], c[1], c[2], c[3]);
        for (const ui::PathSeries& path : run.paths)
            for (std::size_t k = 0; k + 1 < path.size(); ++k)
                add_segment(out, glm::vec3(path.position(k)), glm::vec3(path.position(k + 1)), colour, colour);
    }
}

}  // namespace pl::app
