// The advisor's runs (advisor.hpp): one scene model run on the advice particles until they all
// rest, recording what the metrics compare; and the comparison of two such runs.
#pragma once

#include "physics/studies/advisor.hpp"

#include <limits>

namespace pl {

struct ParticleOutcome {
    std::optional<double> landing_time;    // first floor impact
    std::optional<Vec3> landing;           // the centre at that impact
    std::vector<double> impact_speeds;     // the first advice_impacts floor impacts, |v| before
    std::optional<double> rest_time;       // last event that left it at rest, if at rest at the end
    double apex_height = 0.0;              // before landing, over the floor
    Vec3 start{0.0}, end{0.0};
};

struct RunOutcome {
    std::vector<ParticleOutcome> particles;
    double end_time = 0.0;  // the run stopped here (all at rest, or the duration limit)
    // Measured on request (the reference run): Reynolds range, drag/weight, Mach.
    double re_min = std::numeric_limits<double>::infinity(), re_max = 0.0;
    double max_drag_to_weight = 0.0, max_mach = 0.0;
};

// Runs `model` until every particle rests (or is frozen) or `max_duration` has passed, or
// `cancel` (may be null) is set.
RunOutcome observe_run(const Model& model, const std::vector<ParticleSpec>& particles, double max_duration,
                       bool measure_numbers, const std::atomic<bool>* cancel);

// Every metric of `value` against `baseline` (value - baseline), with the tolerance rule of
// AdviceTolerances; also fills the run's landing/apex maxima and `matters`.
void compare_runs(const RunOutcome& value, const RunOutcome& baseline, const AdviceTolerances& tolerances, ModelRun& out);

}  // namespace pl
