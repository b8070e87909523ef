#include "physics/stepping/experiment.hpp"

#include <algorithm>
#include <cmath>

namespace pl {

FixedStepClock::Tick FixedStepClock::advance(double real_seconds, double dt) {
    Tick tick;
    if (!(real_seconds > 0.0) || !(dt > 0.0)) return tick;
    accumulator_ += real_seconds * time_scale;
    const double whole = std::floor(accumulator_ / dt);
    if (whole > static_cast<double>(max_steps_per_frame)) {
        tick.steps = max_steps_per_frame;
        tick.behind = true;
        accumulator_ = 0.0;  // drop the backlog rather than spiral
        return tick;
    }
    tick.steps = static_cast<std::uint64_t>(whole);
    accumulator_ -= whole * dt;
    return tick;
}

Experiment::Experiment(const Scene& scene) : scene_(scene) { reset(); }

void Experiment::reset() {
    runs_.clear();
    const std::vector<ParticleSpec> particles = initial_particles(scene_);
    const std::size_t n = pl::variant_count(scene_);
    runs_.reserve(n);
    base_dt_ = INFINITY;
    for (std::size_t v = 0; v < n; ++v) {
        runs_.emplace_back(model_for_variant(scene_, v), particles);
        base_dt_ = std::min(base_dt_, runs_.back().dt());
    }
    target_steps_ = 0;
    clock_.reset();
}

void Experiment::step_base(std::uint64_t n) {
    target_steps_ += n;
    const double t = time();
    // A variant with a coarser dt takes its step once the common time reaches it.
    for (Simulation& s : runs_) s.step_n(s.steps_to(t));
}

void Experiment::run_until(double t) {
    const auto target = static_cast<std::uint64_t>(std::ceil(t / base_dt_ * (1.0 - 1e-12)));
    if (target > target_steps_) step_base(target - target_steps_);
}

FixedStepClock::Tick Experiment::advance_real(double real_seconds) {
    const FixedStepClock::Tick tick = clock_.advance(real_seconds, base_dt_);
    if (tick.steps > 0) step_base(tick.steps);
    return tick;
}

}  // namespace pl
