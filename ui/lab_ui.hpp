// The lab's panels. The app shell creates the windows (fixed layout) and calls these between
// ImGui::Begin/End; each draws contents only (it may open child windows and popups).
#pragma once

#include "ui/lab_session.hpp"

#include <cstdint>

namespace pl::ui {

// Call once per frame after physics stepping: takes the new events into the log (drains
// Simulation::events() of every variant). It samples nothing: plot samples come from record_step.
void record_frame(LabSession&);
// After base steps (the shell's after-steps hook, also inside single step and run to the next
// event). With live comparison metrics (up to PlotHistory::max_metrics_particles particles) it
// observes every step, so that they are those of a timed run (the apex and the range at the
// first impact need every step). It samples the plots at fixed simulated intervals
// (PlotHistory::particle_interval_s, aggregate_interval_s), so a plot never depends on the frame
// rate. Returns how many base steps may pass before it must run again: 1 with live metrics,
// otherwise the steps until the next sample is due.
std::uint64_t record_step(LabSession&);
void draw_control_panel(LabSession&);   // left column: preset, time, launch, scene, variants, inspector
void draw_plots_panel(LabSession&);     // height / speed / kinetic energy / energy ledger plots
void draw_analysis_panel(LabSession&);  // bottom tabs: compare, events, ledger, accuracy, stability, advise, warnings
void draw_status_bar(LabSession&);      // one line
void draw_popups(LabSession&);
// Saves the scene over the preset it came from (atomic, previous file kept as .bak); on failure
// the error popup says why and nothing is lost. A shipped preset (read-only) or a scene without
// a file opens the Save As dialog instead (false: not saved yet). Ctrl+S.
bool save_in_place(LabSession&);          // error modal, help overlay, unsaved-changes prompt
// Ctrl+O: opens the Preset section and puts the keyboard in its "open" path field (type a
// path, Enter loads it; a file that does not load shows the error and keeps the scene).
void focus_open_path(LabSession&);

}  // namespace pl::ui
