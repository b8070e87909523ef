#include "physics/model/emitter.hpp"

#include "physics/model/random.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace pl {

std::vector<ParticleSpec> emit_particles(const Emitter& e, const Room& room, std::size_t limit) {
    std::vector<ParticleSpec> out;
    append_emitted(e, room, out, limit);
    return out;
}

void append_emitted(const Emitter& e, const Room& room, std::vector<ParticleSpec>& out, std::size_t limit) {
    SplitMix64 rng(e.seed);
    const std::size_t count = std::min(e.count, limit);
    out.reserve(out.size() + count);
    const Vec3 axis = glm::length(e.direction) > 0 ? e.direction / glm::length(e.direction) : Vec3(0, 1, 0);
    // Orthonormal frame around the axis (Frisvad-style pick of a helper vector).
    const Vec3 helper = std::abs(axis.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
    const Vec3 u = glm::normalize(glm::cross(axis, helper));
    const Vec3 w = glm::cross(axis, u);
    const double cos_max = std::cos(std::clamp(e.spread_deg, 0.0, 180.0) * std::numbers::pi / 180.0);
    const Vec3 lo = room.min_corner(), hi = room.max_corner();
    for (std::size_t i = 0; i < count; ++i) {
        ParticleSpec p;
        p.radius = rng.uniform(e.radius_min, e.radius_max);
        p.mass = rng.uniform(e.mass_min, e.mass_max);
        Vec3 pos{rng.uniform(e.region_min.x, e.region_max.x), rng.uniform(e.region_min.y, e.region_max.y),
                 rng.uniform(e.region_min.z, e.region_max.z)};
        for (int a = 0; a < 3; ++a) {
            const double l = lo[a] + p.radius, h = hi[a] - p.radius;
            pos[a] = l <= h ? std::clamp(pos[a], l, h) : room.center[a];
        }
        p.position = pos;
        // Uniform direction on the spherical cap around the axis.
        const double cz = rng.uniform(cos_max, 1.0);
        const double sz = std::sqrt(std::max(0.0, 1.0 - cz * cz));
        const double phi = rng.uniform(0.0, 2.0 * std::numbers::pi);
        const Vec3 dir = cz * axis + sz * (std::cos(phi) * u + std::sin(phi) * w);
        p.velocity = rng.uniform(e.speed_min, e.speed_max) * dir;
        out.push_back(p);
    }
}

}  // namespace pl
