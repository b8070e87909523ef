#include "physics/studies/collision_estimate.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

namespace pl {

namespace {

constexpr double pi = std::numbers::pi;

// The floor: the room's wall on the axis gravity mostly points along, on the side it points to.
struct Floor {
    int axis = -1;     // -1: no gravity, no floor
    double coordinate = 0.0;
    double g = 0.0;    // gravity's component into the floor, m/s^2
    double area_m2 = 0.0;
};

Floor floor_of(const Model& model) {
    const Vec3& g = model.world.gravity;
    Floor f;
    if (g == Vec3(0.0)) return f;
    f.axis = 0;
    for (int a = 1; a < 3; ++a)
        if (std::abs(g[a]) > std::abs(g[f.axis])) f.axis = a;
    const Room& room = model.room;
    f.coordinate = g[f.axis] < 0.0 ? room.min_corner()[f.axis] : room.max_corner()[f.axis];
    f.g = std::abs(g[f.axis]);
    f.area_m2 = room.size[(f.axis + 1) % 3] * room.size[(f.axis + 2) % 3];
    return f;
}

// rms of sqrt(|v0|^2 + 2 g h): each particle's speed at the floor after a drag-free fall.
double characteristic_speed(const Floor& floor, std::span<const ParticleSpec> particles) {
    double sum_v2 = 0.0;
    for (const ParticleSpec& p : particles) {
        const double h = floor.axis < 0 ? 0.0 : std::max(0.0, std::abs(p.position[floor.axis] - floor.coordinate) - p.radius);
        sum_v2 += glm::dot(p.velocity, p.velocity) + 2.0 * floor.g * h;
    }
    return std::sqrt(sum_v2 / static_cast<double>(particles.size()));
}

}  // namespace

double mean_pair_cross_section(std::span<const ParticleSpec> particles) {
    const double n = static_cast<double>(particles.size());
    if (particles.size() < 2) return 0.0;
    double s1 = 0.0, s2 = 0.0;
    for (const ParticleSpec& p : particles) {
        s1 += p.radius;
        s2 += p.radius * p.radius;
    }
    const double pairs = 0.5 * n * (n - 1.0);
    return pi * ((n - 2.0) * s2 + s1 * s1) / pairs;
}

CollisionEstimate estimate_collisions(const Model& model, std::span<const ParticleSpec> particles, double duration_s) {
    CollisionEstimate e;
    e.particles = particles.size();
    e.duration_s = duration_s;
    e.applicable = particles.size() >= 2;
    if (!e.applicable) return e;
    const Room& room = model.room;
    e.room_volume_m3 = room.size.x * room.size.y * room.size.z;
    const double n = static_cast<double>(particles.size());
    e.number_density_m3 = n / e.room_volume_m3;
    for (const ParticleSpec& p : particles) {
        e.volume_fraction += 4.0 / 3.0 * pi * p.radius * p.radius * p.radius / e.room_volume_m3;
        e.footprint_m2 += pi * p.radius * p.radius;
    }
    e.cross_section_m2 = mean_pair_cross_section(particles);
    const double n_sigma = e.number_density_m3 * e.cross_section_m2;
    if (n_sigma > 0.0) e.mean_free_path_m = 1.0 / (std::numbers::sqrt2 * n_sigma);
    const Floor floor = floor_of(model);
    e.speed_m_s = characteristic_speed(floor, particles);
    e.rate_per_s = e.speed_m_s / e.mean_free_path_m;
    e.per_particle = e.rate_per_s * duration_s;
    e.total = 0.5 * n * e.per_particle;
    e.floor_area_m2 = floor.area_m2;
    if (floor.area_m2 > 0.0) e.layers = e.footprint_m2 / (disk_random_close_packing * floor.area_m2);
    e.must_stack = e.layers > 1.0;
    e.matters = e.must_stack || e.total >= collisions_that_matter;
    return e;
}

std::string collision_reason(const CollisionEstimate& e) {
    if (!e.applicable) return "one particle: nothing to collide with";
    if (e.must_stack)
        return fmt::format("{} balls cannot lie in one layer on {:.3g} m^2 of floor (they need {:.2g} layers)", e.particles,
                           e.floor_area_m2, e.layers);
    return fmt::format("{:.2g} expected collisions per particle over {:.3g} s ({:.2g} in all; mean free path {:.3g} m, "
                       "volume fraction {:.2g})",
                       e.per_particle, e.duration_s, e.total, e.mean_free_path_m, e.volume_fraction);
}

}  // namespace pl
