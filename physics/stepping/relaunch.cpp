#include "physics/stepping/relaunch.hpp"

#include "physics/model/air_model.hpp"
#include "physics/stepping/contact.hpp"
#include "physics/stepping/energy.hpp"

namespace pl {

void relaunch_particle(Simulation& sim, std::size_t i, const Vec3& position, const Vec3& velocity) {
    ParticleState& s = sim.state_;
    const Model& m = sim.model();
    const double mass = s.mass[i];
    const Vec3 inside = RoomBounds(m.room).clamp_inside(position, s.radius[i]);
    const double before = kinetic_energy(s.inertial_mass[i], s.velocity(i)) +
                          potential_energy(m.world.gravity, m.room, mass, s.position(i));
    // The kinetic energy at the new height (with added mass, M depends on the air there).
    const double inertial = inertial_mass(m.world, m.room, mass, s.radius[i], inside.y);
    const double after = kinetic_energy(inertial, velocity) + potential_energy(m.world.gravity, m.room, mass, inside);
    s.initial_energy[i] += after - before;
    s.resting[i] = 0;
    s.frozen[i] = 0;
    s.set_position(i, inside);
    s.inertial_mass[i] = inertial;
    sim.set_velocity(i, velocity);
    if (!sim.adaptive_step_hint_.empty()) sim.adaptive_step_hint_[i] = 0.0;  // dopri5 picks a fresh first step
}

}  // namespace pl
