#include "app/renderer_arrows.hpp"

#include "ui/palette.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace pl::app {

namespace {

// The 1-2-5 value nearest to `raw` from below.
float nice_time(double raw) {
    const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
    double best = magnitude;
    for (double m : {1.0, 2.0, 5.0})
        if (m * magnitude <= raw) best = m * magnitude;
    return static_cast<float>(best);
}

double room_extent(const Room& room) { return std::max({room.size.x, room.size.y, room.size.z}); }

}  // namespace

float velocity_arrow_time_s(const Room& room) { return nice_time(room_extent(room) / 40.0); }
float wind_arrow_time_s(const Room& room) { return nice_time(room_extent(room) / 25.0); }

void append_arrow(LineSegments& out, glm::vec3 from, glm::vec3 to, glm::vec4 color, glm::vec3 view_dir) {
    const glm::vec3 shaft = to - from;
    const float length = glm::length(shaft);
    if (!(length > 1e-6f)) return;
    const glm::vec3 dir = shaft / length;
    glm::vec3 side = glm::cross(dir, view_dir);
    if (glm::length(side) < 1e-4f) side = glm::cross(dir, glm::vec3(0.0f, 1.0f, 0.001f));
    side = glm::normalize(side);
    const float head = std::min(0.3f * length, 0.25f * length + 0.02f);
    add_segment(out, from, to, color);
    add_segment(out, to, to - dir * head + side * (0.5f * head), color);
    add_segment(out, to, to - dir * head - side * (0.5f * head), color);
}

void append_velocity_arrows(const Experiment& e, std::optional<std::size_t> only_variant, glm::vec3 view_dir,
                            LineSegments& out) {
    const std::size_t variants = e.variant_count();
    for (std::size_t v = 0; v < variants; ++v) {
        if (only_variant && v != *only_variant) continue;
        const ParticleState& s = e.run(v).state();
        const float time_s = velocity_arrow_time_s(e.run(v).model().room);
        const std::size_t n = std::min(s.size(), max_velocity_arrows_per_variant);
        for (std::size_t i = 0; i < n; ++i) {
            const ui::Rgb c = ui::series_color(variants, v, i);
            const glm::vec3 x(s.position(i));
            const glm::vec3 vel(s.velocity(i));
            // Start at the sphere's surface so the arrow is visible on large spheres.
            const float speed = glm::length(vel);
            if (!(speed > 1e-6f)) continue;
            const glm::vec3 start = x + vel / speed * static_cast<float>(s.radius[i]);
            append_arrow(out, start, start + vel * time_s,
                         glm::vec4(0.5f + 0.5f * c.r, 0.5f + 0.5f * c.g, 0.5f + 0.5f * c.b, 0.95f), view_dir);
        }
    }
}

std::optional<std::size_t> wind_variant_to_show(const Experiment& e, std::optional<std::size_t> pane_variant,
                                                std::size_t selected_variant) {
    auto has_wind = [&](std::size_t v) { return v < e.variant_count() && e.run(v).wind().kind() != WindKind::none; };
    if (pane_variant) return has_wind(*pane_variant) ? pane_variant : std::nullopt;
    if (has_wind(selected_variant)) return selected_variant;
    for (std::size_t v = 0; v < e.variant_count(); ++v)
        if (has_wind(v)) return v;
    return std::nullopt;
}

void append_wind_arrows(const Experiment& e, std::size_t variant, glm::vec3 view_dir, LineSegments& out) {
    const Simulation& sim = e.run(variant);
    if (sim.wind().kind() == WindKind::none) return;
    const Room& room = sim.model().room;
    const Vec3 lo = room.min_corner(), size = room.size;
    constexpr int nx = 6, ny = 4, nz = 6;
    const glm::vec4 color(0.55f, 0.85f, 0.95f, 0.55f);
    for (int i = 0; i < nx; ++i)
        for (int j = 0; j < ny; ++j)
            for (int k = 0; k < nz; ++k) {
                const Vec3 p = lo + Vec3((i + 0.5) / nx * size.x, (j + 0.5) / ny * size.y, (k + 0.5) / nz * size.z);
                const glm::vec3 w(sim.wind().at(p, e.time()));
                const glm::vec3 from(p);
                append_arrow(out, from, from + w * wind_arrow_time_s(room), color, view_dir);
            }
}

}  // namespace pl::app
