#include "physics/stepping/energy.hpp"

#include <glm/geometric.hpp>

namespace pl {

double potential_energy(const Vec3& g, const Room& room, double mass, const Vec3& p) {
    const Vec3 lo = room.min_corner(), hi = room.max_corner();
    const Vec3 ref{g.x < 0 ? lo.x : hi.x, g.y < 0 ? lo.y : hi.y, g.z < 0 ? lo.z : hi.z};
    return -mass * glm::dot(g, p - ref);
}

double kinetic_energy(double mass, const Vec3& v) { return 0.5 * mass * glm::dot(v, v); }

double spin_energy(double mass, double radius, double inertia, const Vec3& w) {
    return 0.5 * inertia * mass * radius * radius * glm::dot(w, w);
}

EnergyBreakdown particle_energy(const ParticleState& s, std::size_t i, const Vec3& g, const Room& room) {
    EnergyBreakdown e;
    e.kinetic = kinetic_energy(s.inertial_mass[i], s.velocity(i));
    e.potential = potential_energy(g, room, s.mass[i], s.position(i));
    e.spin = spin_energy(s.mass[i], s.radius[i], s.inertia[i], s.spin(i));
    e.dissipated_rolling = s.dissipated_rolling[i];
    e.dissipated_bounce = s.dissipated_bounce[i];
    e.dissipated_friction = s.dissipated_friction[i];
    e.dissipated_drag = s.dissipated_drag[i];
    e.wind_work = s.wind_work[i];
    e.collision_work = s.collision_work.empty() ? 0.0 : s.collision_work[i];
    e.initial = s.initial_energy[i];
    return e;
}

EnergyBreakdown total_energy(const ParticleState& s, const Vec3& g, const Room& room) {
    EnergyBreakdown sum;
    for (std::size_t i = 0; i < s.size(); ++i) {
        const EnergyBreakdown e = particle_energy(s, i, g, room);
        sum.kinetic += e.kinetic;
        sum.potential += e.potential;
        sum.spin += e.spin;
        sum.dissipated_rolling += e.dissipated_rolling;
        sum.dissipated_bounce += e.dissipated_bounce;
        sum.dissipated_friction += e.dissipated_friction;
        sum.dissipated_drag += e.dissipated_drag;
        sum.wind_work += e.wind_work;
        sum.collision_work += e.collision_work;
        sum.initial += e.initial;
    }
    return sum;
}

}  // namespace pl
