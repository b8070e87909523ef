// Fills the session's PlotHistory from the running experiment: plot samples, the event log and
// the live comparison metrics (physics/studies/metrics.hpp). No ImGui.
#pragma once

#include "ui/lab_session.hpp"
#include "ui/plot_history.hpp"

namespace pl::ui {

// The session's history, created on first use and started over when the experiment was
// replaced or went back in time (reset, load, edit).
PlotHistory& history_of(LabSession& s);

// Particle i of every variant gets a new launch state at the current time (a kick from the
// inspector): its metrics start over from here. The ledger is kept honest (relaunch_particle).
void kick_particle(LabSession& s, std::size_t i, const Vec3& velocity);

}  // namespace pl::ui
