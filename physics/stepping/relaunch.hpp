// Launching a particle again mid-run (the GUI's L key and launch tool): a new initial state for
// one particle while the rest of the run continues.
#pragma once

#include "physics/stepping/simulation.hpp"

namespace pl {

// Puts particle i at `position` with `velocity`: it leaves any wall it rested on and is no
// longer frozen. The mechanical energy this adds or removes is credited to the particle's
// initial energy, so the ledger's residual stays the integrator's own error.
void relaunch_particle(Simulation& sim, std::size_t i, const Vec3& position, const Vec3& velocity);

}  // namespace pl
