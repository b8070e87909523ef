// Invariants the engine relies on, checked where a simulation is built (Simulation's
// constructor): a Model built in code, not read from a preset, gets the same protection as a
// preset's reader gives. Only what would make the stepping meaningless or endless is refused
// (a preset's reader also applies its sane-size limits); a velocity may be huge, never NaN.
#pragma once

#include "physics/model/scene.hpp"

#include <vector>

namespace pl {

// Throws std::invalid_argument naming the field and the rule broken, e.g.
// "integrator.dt: must be finite and > 0, got 0" or "particles[2].radius: must be finite and > 0, got -1".
void check_model(const Model& model, const std::vector<ParticleSpec>& particles);

}  // namespace pl
