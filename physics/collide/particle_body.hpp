// A particle as the impulses see it (narrow_phase.hpp's Body), and its energy of motion.
#pragma once

#include "physics/collide/narrow_phase.hpp"
#include "physics/stepping/energy.hpp"
#include "physics/stepping/particle_state.hpp"

namespace pl::collide {

// The inertial mass M (m with added mass off): the impulses move what the forces move, and the
// ledger's kinetic energy is 1/2 M v^2.
inline Body body_of(const ParticleState& s, std::uint32_t i) {
    return {s.velocity(i), s.spin(i), s.inertial_mass[i], s.radius[i], s.moment(i)};
}

inline double motion_energy(const ParticleState& s, std::uint32_t i) {
    return kinetic_energy(s.inertial_mass[i], s.velocity(i)) + spin_energy(s.mass[i], s.radius[i], s.inertia[i], s.spin(i));
}

}  // namespace pl::collide
