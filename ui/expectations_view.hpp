// The preset's expectations ("expect") beside the live measurements: the Compare tab's live
// metrics (ui/plot_history.hpp trackers) checked by physics/studies/expectations.hpp.
#pragma once

#include "physics/studies/expectations.hpp"
#include "ui/lab_session.hpp"

#include <vector>

namespace pl::ui {

// One result per expectation of the scene; measured empty while the live metrics are off (more
// particles than PlotHistory::max_metrics_particles) or the quantity has no value yet.
std::vector<ExpectationResult> live_expectations(const LabSession& s);

// A table under the description: quantity, variant and particle, expected +- tolerance,
// measured (green when within tolerance).
void draw_expectations(LabSession& s);

}  // namespace pl::ui
