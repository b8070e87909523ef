#include "physics/model/start_packing.hpp"

#include <glm/common.hpp>

#include <algorithm>
#include <numbers>

namespace pl {
namespace {

// `count` balls of mean radius `mean_r` and mean cube `mean_r3` in a box of centres with these
// sides, grown by the mean radius.
double fraction_in_box(double count, double mean_r, double mean_r3, const Vec3& sides) {
    double space = 1.0;
    for (int a = 0; a < 3; ++a) space *= std::max(sides[a], 0.0) + 2.0 * mean_r;
    return count * 4.0 / 3.0 * std::numbers::pi * mean_r3 / space;
}

}  // namespace

double emitted_volume_fraction(const Emitter& e, const Room& room) {
    if (e.count == 0) return 0.0;
    // The mean of r^3 and of r for r uniform in [radius_min, radius_max].
    const double r0 = e.radius_min, r1 = e.radius_max;
    const double mean_r3 = r1 > r0 ? (r1 * r1 * r1 * r1 - r0 * r0 * r0 * r0) / (4.0 * (r1 - r0)) : r0 * r0 * r0;
    const Vec3 lo = room.min_corner(), hi = room.max_corner();
    Vec3 sides;
    for (int a = 0; a < 3; ++a)
        sides[a] = std::min(e.region_max[a], hi[a] - r0) - std::max(e.region_min[a], lo[a] + r0);
    return fraction_in_box(static_cast<double>(e.count), 0.5 * (r0 + r1), mean_r3, sides);
}

double listed_volume_fraction(const std::vector<ParticleSpec>& particles) {
    if (particles.empty()) return 0.0;
    Vec3 lo = particles.front().position, hi = lo;
    double sum_r = 0.0, sum_r3 = 0.0;
    for (const ParticleSpec& p : particles) {
        lo = glm::min(lo, p.position);
        hi = glm::max(hi, p.position);
        sum_r += p.radius;
        sum_r3 += p.radius * p.radius * p.radius;
    }
    const auto n = static_cast<double>(particles.size());
    return fraction_in_box(n, sum_r / n, sum_r3 / n, hi - lo);
}

}  // namespace pl
