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

// Under the description, per expectation: the quantity (with its particle and variant), then
// expected +- tolerance and the measured value (green when within the tolerance).
void draw_expectations(LabSession& s);

}  // namespace pl::ui
