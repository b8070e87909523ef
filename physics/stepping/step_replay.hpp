// Replays one particle's latest step of a Simulation with a StepTrace (step_trace.hpp): what the
// comparison metrics use to measure the apex and the first impact on the step's own trajectory
// rather than at step ends. The replay runs the generic stepper (ParticleStepper, bit-identical
// to the fast kernel) from the particle's state before the step, for that one particle only, so
// the stepping kernels pay nothing for it.
#pragma once

#include "physics/stepping/simulation.hpp"
#include "physics/stepping/step_trace.hpp"

#include <cstdint>
#include <optional>

namespace pl {

// The evolving part of one particle's state that a step starts from.
struct StepStart {
    Vec3 x{0.0}, v{0.0};
    std::uint8_t resting = 0;
    Vec3 spin{0.0};          // read where the model's spin_matters
    double step_hint = 0.0;  // adaptive Dormand-Prince's next internal step
};

// Sets `start` to particle i's state now, as the start of the next step (the spin and the step
// hint only where the model uses them: metrics do this for every particle after every step).
inline void update_step_start(StepStart& start, const Simulation& sim, std::size_t i) {
    const ParticleState& s = sim.state();
    start.x = s.position(i);
    start.v = s.velocity(i);
    start.resting = s.resting[i];
    if (spin_matters(sim.model())) start.spin = s.spin(i);
    if (sim.model().integrator.method == Method::dopri5) start.step_hint = sim.adaptive_step_hint(i);
}

// The trace of particle i's latest step (the one that ended at sim.time()) replayed from
// `before`; empty when no step was taken, the particle is frozen, or the replay does not end in
// the particle's current position and velocity bit for bit (then `before` was not the state that
// step started from: a particle launched again in between).
std::optional<StepTrace> replay_step(const Simulation& sim, std::size_t i, const StepStart& before);

}  // namespace pl
