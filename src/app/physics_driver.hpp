// Runs the physics for one GUI frame: real time x time scale -> whole fixed steps, within a
// wall-clock budget so the UI never freezes (steps that do not fit are dropped and the frame is
// reported behind; the trajectory itself never depends on the frame rate).
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

// `budget_s` <= 0 runs every step the clock asks for (deterministic test runs); otherwise the
// budget is checked between groups of steps.
FrameAdvance advance_frame(Experiment& experiment, double real_dt_s, double time_scale, double budget_s,
                           const AfterSteps& after_steps);

}  // namespace pl::app
