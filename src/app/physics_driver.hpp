// Runs the physics for one GUI frame: real time x time scale -> whole fixed steps, within a
// wall-clock budget so the UI never freezes (steps that do not fit are dropped and the frame is
// reported behind; the trajectory itself never depends on the frame rate).
#pragma once

#include "physics/experiment.hpp"

#include <cstdint>
#include <functional>

namespace pl::app {

struct FrameAdvance {
    std::uint64_t steps = 0;  // base steps run
    bool behind = false;      // the clock's cap or the budget dropped steps
    double physics_ms = 0.0;  // wall time spent stepping
};

// `budget_s` <= 0 runs every step the clock asks for (deterministic test runs).
// `after_step` runs after every base step (trail sampling).
FrameAdvance advance_frame(Experiment& experiment, double real_dt_s, double time_scale, double budget_s,
                           const std::function<void()>& after_step);

}  // namespace pl::app
