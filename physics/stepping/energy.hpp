// Energy bookkeeping: E0 + wind work + collision work = KE + spin KE + PE + dissipated (bounce,
// friction, drag, rolling) + residual. With added mass, KE = 1/2 (m + m_a) v^2 and PE = m g h
// (terms/air_column.hpp). The collision work moves energy between particles and, summed over all
// of them, is minus what the collisions dissipated.
// The residual is the integrator's own energy error.
#pragma once

#include "physics/stepping/particle_state.hpp"

namespace pl {

struct EnergyBreakdown {
    double kinetic = 0, potential = 0;
    double spin = 0;  // rotational kinetic energy 1/2 I |w|^2
    double dissipated_bounce = 0, dissipated_friction = 0, dissipated_drag = 0;
    double dissipated_rolling = 0;  // by rolling resistance
    double wind_work = 0;
    double collision_work = 0;  // given by particle-particle impulses (collisions.enabled)
    double initial = 0;
    double residual() const {
        return initial + wind_work + collision_work -
               (kinetic + spin + potential + dissipated_bounce + dissipated_friction + dissipated_drag + dissipated_rolling);
    }
    double total_mechanical() const { return kinetic + spin + potential; }
};

// Gravitational potential relative to the room's lowest point along g (>= 0 inside the room).
double potential_energy(const Vec3& gravity, const Room& room, double mass, const Vec3& position);
double kinetic_energy(double mass, const Vec3& velocity);
// 1/2 I |w|^2 with I = k m R^2 (k: ParticleState::inertia).
double spin_energy(double mass, double radius, double inertia, const Vec3& spin);

EnergyBreakdown particle_energy(const ParticleState& s, std::size_t i, const Vec3& gravity, const Room& room);
EnergyBreakdown total_energy(const ParticleState& s, const Vec3& gravity, const Room& room);

}  // namespace pl
