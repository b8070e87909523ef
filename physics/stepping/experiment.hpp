// Experiment: every variant of a scene as its own Simulation, advanced in lockstep to a common
// simulated time, plus the fixed-step clock the GUI drives with real frame times.
#pragma once

#include "physics/model/scene.hpp"
#include "physics/stepping/simulation.hpp"

#include <cstdint>
#include <vector>

namespace pl {

// Turns real frame times into a simulated-time target. Whole steps only; at most
// max_steps_per_frame per call, beyond which the clock drops the backlog and reports it.
struct FixedStepClock {
    double time_scale = 1.0;
    std::uint64_t max_steps_per_frame = 2000;

    struct Tick {
        std::uint64_t steps = 0;  // steps of the finest dt to run this frame
        bool behind = false;      // real time could not be followed this frame
    };
    // `dt` is the step the budget is counted in (the smallest dt of the variants).
    Tick advance(double real_seconds, double dt);
    void reset() { accumulator_ = 0.0; }
    double backlog() const { return accumulator_; }

private:
    double accumulator_ = 0.0;  // simulated seconds owed, < dt after each tick
};

class Experiment {
public:
    explicit Experiment(const Scene& scene);

    const Scene& scene() const { return scene_; }
    std::size_t variant_count() const { return runs_.size(); }
    Simulation& run(std::size_t v) { return runs_[v]; }
    const Simulation& run(std::size_t v) const { return runs_[v]; }
    const std::vector<Simulation>& runs() const { return runs_; }

    // Simulated time common to all variants (each variant is at the last step of its own dt
    // not after it).
    double time() const { return target_steps_ * base_dt_; }
    double base_dt() const { return base_dt_; }
    std::uint64_t base_steps() const { return target_steps_; }

    // Advances every variant by `n` steps of the base (smallest) dt.
    void step_base(std::uint64_t n = 1);
    // Runs until time() >= t.
    void run_until(double t);
    // Frame entry point: real seconds since the last frame -> whole steps.
    FixedStepClock::Tick advance_real(double real_seconds);
    FixedStepClock& clock() { return clock_; }

    // Restarts every variant from the scene's initial particles.
    void reset();

private:
    Scene scene_;
    std::vector<Simulation> runs_;
    double base_dt_ = 0.0;
    std::uint64_t target_steps_ = 0;
    FixedStepClock clock_;
};

}  // namespace pl
