#include "physics/model/start_packing.hpp"

#include "physics/collide/collision_pass.hpp"

#include <algorithm>
#include <numbers>

namespace pl {

double emitted_volume_fraction(const Emitter& e, const Room& room) {
    if (e.count == 0) return 0.0;
    // The mean of r^3 and of r for r uniform in [radius_min, radius_max].
    const double r0 = e.radius_min, r1 = e.radius_max;
    const double mean_r3 = r1 > r0 ? (r1 * r1 * r1 * r1 - r0 * r0 * r0 * r0) / (4.0 * (r1 - r0)) : r0 * r0 * r0;
    const double mean_r = 0.5 * (r0 + r1);
    // The box of centres clamped into the room, grown by the mean radius on every side.
    const Vec3 lo = room.min_corner(), hi = room.max_corner();
    double space = 1.0;
    for (int a = 0; a < 3; ++a) {
        const double side = std::min(e.region_max[a], hi[a] - r0) - std::max(e.region_min[a], lo[a] + r0);
        space *= std::max(side, 0.0) + 2.0 * mean_r;
    }
    return static_cast<double>(e.count) * 4.0 / 3.0 * std::numbers::pi * mean_r3 / space;
}

OverlapCount listed_overlaps(const std::vector<ParticleSpec>& particles) {
    std::vector<Sphere> spheres;
    spheres.reserve(particles.size());
    for (const ParticleSpec& p : particles) spheres.push_back({p.position, p.radius});
    const auto limit = static_cast<std::size_t>(max_start_overlaps_per_ball * static_cast<double>(particles.size()));
    return count_overlaps(spheres, limit, collide::CollisionPass::allowed_overlap);
}

}  // namespace pl
