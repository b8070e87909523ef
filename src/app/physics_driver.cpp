#include "app/physics_driver.hpp"

#include <chrono>

namespace pl::app {

FrameAdvance advance_frame(Experiment& experiment, double real_dt_s, double time_scale, double budget_s,
                           const std::function<void()>& after_step) {
    using clock = std::chrono::steady_clock;
    const clock::time_point start = clock::now();
    auto elapsed_s = [&] { return std::chrono::duration<double>(clock::now() - start).count(); };

    experiment.clock().time_scale = time_scale;
    const FixedStepClock::Tick tick = experiment.clock().advance(real_dt_s, experiment.base_dt());
    FrameAdvance out;
    out.behind = tick.behind;
    for (; out.steps < tick.steps; ++out.steps) {
        if (budget_s > 0.0 && out.steps > 0 && elapsed_s() > budget_s) {
            out.behind = true;
            break;
        }
        experiment.step_base(1);
        if (after_step) after_step();
    }
    out.physics_ms = 1e3 * elapsed_s();
    return out;
}

}  // namespace pl::app
