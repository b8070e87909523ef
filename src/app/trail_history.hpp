// Recent positions of the tracked particles (the first N of every variant, N chosen in the view
// toolbar, plus the selected one), sampled in simulated time so a trail's shape does not depend
// on the frame rate.
#pragma once

#include "physics/stepping/experiment.hpp"

#include <glm/vec3.hpp>

#include <cstddef>
#include <vector>

namespace pl::app {

struct Trail {
    std::size_t variant = 0, particle = 0;
    std::vector<glm::vec3> points;  // ring buffer
    std::vector<double> times;      // simulated time of each point, s (same ring)
    std::size_t head = 0;           // next slot to write
    std::size_t count = 0;          // valid samples
    // Oldest first: k = 0 .. count-1.
    const glm::vec3& at(std::size_t k) const { return points[slot(k)]; }
    double time_at(std::size_t k) const { return times[slot(k)]; }
    std::size_t slot(std::size_t k) const { return (head + points.size() - count + k) % points.size(); }
};

class TrailHistory {
public:
    static constexpr std::size_t max_per_variant = 256;  // the most trails the toolbar offers per variant
    static constexpr std::size_t max_variants = 16;
    static constexpr std::size_t capacity = 1600;      // samples per trail (8 s)
    static constexpr double sample_interval_s = 1.0 / 200.0;  // simulated seconds between samples

    // Starts over when the experiment was replaced or went back in time (reset, load).
    void sync(const Experiment* experiment);
    void clear();
    // Records the first `per_variant` particles of each variant and the selected one, if a sample
    // interval has passed since the last sample.
    void sample(const Experiment& experiment, std::size_t selected_particle, std::size_t per_variant);
    // Base steps from now after which sample() records again (at least 1, at most 64).
    std::uint64_t steps_until_due(const Experiment& experiment) const;
    const std::vector<Trail>& trails() const { return trails_; }

private:
    Trail& trail_for(std::size_t variant, std::size_t particle);

    std::vector<Trail> trails_;
    const Experiment* experiment_ = nullptr;
    std::uint64_t last_steps_ = 0;
    double last_sample_t_ = -1.0;
};

}  // namespace pl::app
