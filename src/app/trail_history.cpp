#include "app/trail_history.hpp"

#include <algorithm>

namespace pl::app {

void TrailHistory::clear() {
    trails_.clear();
    last_sample_t_ = -1.0;
}

void TrailHistory::sync(const Experiment* experiment) {
    const std::uint64_t steps = experiment ? experiment->base_steps() : 0;
    if (experiment != experiment_ || steps < last_steps_) clear();
    experiment_ = experiment;
    last_steps_ = steps;
}

Trail& TrailHistory::trail_for(std::size_t variant, std::size_t particle) {
    for (Trail& t : trails_)
        if (t.variant == variant && t.particle == particle) return t;
    Trail t;
    t.variant = variant;
    t.particle = particle;
    t.points.resize(capacity);
    t.times.resize(capacity);
    trails_.push_back(std::move(t));
    return trails_.back();
}

std::uint64_t TrailHistory::steps_until_due(const Experiment& e) const {
    if (&e != experiment_ || last_sample_t_ < 0.0) return 1;
    // The test sample() makes, at the experiment's time after k more base steps.
    std::uint64_t k = 1;
    while (k < 64 && static_cast<double>(e.base_steps() + k) * e.base_dt() - last_sample_t_ < sample_interval_s) ++k;
    return k;
}

void TrailHistory::sample(const Experiment& e, std::size_t selected_particle, std::size_t per_variant) {
    sync(&e);
    const double t = e.time();
    if (last_sample_t_ >= 0.0 && t - last_sample_t_ < sample_interval_s) return;
    last_sample_t_ = t;
    const std::size_t variants = std::min(e.variant_count(), max_variants);
    for (std::size_t v = 0; v < variants; ++v) {
        const ParticleState& s = e.run(v).state();
        auto record = [&](std::size_t i) {
            Trail& trail = trail_for(v, i);
            trail.points[trail.head] = glm::vec3(s.position(i));
            trail.times[trail.head] = t;
            trail.head = (trail.head + 1) % capacity;
            trail.count = std::min(trail.count + 1, capacity);
        };
        const std::size_t tracked = std::min({s.size(), per_variant, max_per_variant});
        for (std::size_t i = 0; i < tracked; ++i) record(i);
        if (selected_particle >= tracked && selected_particle < s.size()) record(selected_particle);
    }
}

}  // namespace pl::app
