#include "app/physics_driver.hpp"

#include <algorithm>
#include <chrono>

namespace pl::app {

FrameAdvance run_steps(Experiment& experiment, std::uint64_t steps, double budget_s, const AfterSteps& after_steps) {
    using clock = std::chrono::steady_clock;
    const clock::time_point start = clock::now();
    auto elapsed_s = [&] { return std::chrono::duration<double>(clock::now() - start).count(); };
    FrameAdvance out;
    std::uint64_t group = 1;  // steps until the hook must run again
    while (out.steps < steps) {
        if (budget_s > 0.0 && out.steps > 0 && elapsed_s() > budget_s) {
            out.behind = true;
            break;
        }
        const std::uint64_t n = std::min(group, steps - out.steps);
        experiment.step_base(n);
        out.steps += n;
        group = after_steps ? std::max<std::uint64_t>(after_steps(), 1) : steps;
    }
    out.physics_ms = 1e3 * elapsed_s();
    return out;
}

FrameAdvance advance_frame(Experiment& experiment, double real_dt_s, double time_scale, double budget_s,
                           const AfterSteps& after_steps) {
    experiment.clock().time_scale = time_scale;
    const FixedStepClock::Tick tick = experiment.clock().advance(real_dt_s, experiment.base_dt());
    FrameAdvance out = run_steps(experiment, tick.steps, budget_s, after_steps);
    out.behind = out.behind || tick.behind;
    return out;
}

}  // namespace pl::app
