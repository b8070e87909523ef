// Runs the physics for one slice of real time (a slice of the physics thread, or a frame on the
// fixed clock): real time x time scale -> whole fixed steps, within a wall-clock budget so the UI
// is never shut out for long (steps that do not fit are dropped and the slice is reported
// behind; the trajectory itself never depends on where slices fall).
#pragma once

#include "physics/stepping/experiment.hpp"

#include <cstdint>
#include <functional>

namespace pl::app {

struct FrameAdvance {
    std::uint64_t steps = 0;  // base steps run
    bool behind = false;      // the clock's cap or the budget dropped steps
    double physics_ms = 0.0;  // wall time spent stepping
};

// A hook that runs after base steps (trail sampling) and returns how many base steps may pass
// before it must run again (at least 1): the steps in between are taken in one
// Experiment::step_base call, which lets the kernel take several per call (Simulation::step_n).
using AfterSteps = std::function<std::uint64_t()>;

// Runs `steps` base steps, or fewer when `budget_s` > 0 runs out (checked between groups of
// steps; then `behind` is set).
FrameAdvance run_steps(Experiment& experiment, std::uint64_t steps, double budget_s, const AfterSteps& after_steps);

// The steps the experiment's clock owes for `real_dt_s` x `time_scale`, through run_steps: steps
// the budget leaves out are dropped. `budget_s` <= 0 runs every step the clock asks for
// (deterministic runs, recordings).
FrameAdvance advance_frame(Experiment& experiment, double real_dt_s, double time_scale, double budget_s,
                           const AfterSteps& after_steps);

}  // namespace pl::app
