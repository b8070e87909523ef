// The parts of the lab's panels, one file each; lab_ui.cpp puts them together.
#pragma once

#include "ui/lab_session.hpp"

#include <imgui.h>

#include <string>
#include <utility>
#include <vector>

namespace pl::ui {

// Control panel
void draw_preset_section(LabSession& s);
void draw_about_section(LabSession& s);  // the preset's description, in full
void draw_runs_section(LabSession& s);   // pin the run, list and unpin pinned runs
void draw_time_section(LabSession& s);
void draw_launch_section(LabSession& s);
void draw_scene_section(LabSession& s);
void draw_variants_section(LabSession& s);
void draw_inspector_section(LabSession& s);

// Analysis tabs
void draw_compare_tab(LabSession& s);
void draw_events_tab(LabSession& s);
void draw_ledger_tab(LabSession& s);
void draw_accuracy_tab(LabSession& s);
void draw_stability_tab(LabSession& s);
void draw_advise_tab(LabSession& s);
void draw_warnings_tab(LabSession& s);

// Popups
// Asks about s.pending (unsaved edits would be lost): Save / Discard / Cancel.
void draw_unsaved_prompt(LabSession& s);

// Shared bits
std::string variant_name(const LabSession& s, std::size_t v);  // label, or "variant N"
std::size_t warning_count(const LabSession& s);  // warnings that put a number at risk (warning_risk.hpp)
std::size_t note_count(const LabSession& s);     // the others: out of range with a negligible error
// The status bar's collision counters summed over the variants: "N collisions (M in the last
// step) · R resting contacts · S asleep"; empty when no variant has collisions on.
std::string collision_status(const LabSession& s);
// Records the last item's screen rectangle under `name` in s.widget_rects, if it is visible.
void note_item_rect(LabSession& s, const std::string& name);
// Saves the scene to `file`; false (and an error dialog) when it cannot.
bool save_scene_to(LabSession& s, const std::filesystem::path& file);
// Plot exports: <export folder (default: cwd)>/<export stem>-<plot><extension>; CSV text written there (status line or
// error dialog); a picture of [min, max] taken two frames later (the menu that asked is gone).
std::filesystem::path export_path(const PanelState& p, const std::string& plot, const char* extension);
// A file that exists already is not written until the user answers "Overwrite?" (Overwrite /
// Cancel: draw_export_question, ui/export_question.cpp).
void write_csv(LabSession& s, const std::filesystem::path& file, const std::string& csv);
void ask_picture(LabSession& s, const std::filesystem::path& file, ImVec2 min, ImVec2 max);
bool export_question_open(const LabSession& s);
void draw_export_question(LabSession& s);
void draw_sweep_tab(LabSession& s);
// The Sweep tab's last result for the state dump: points, points run, and per line series its
// label and the first axis's value at the series' largest metric value.
struct SweepSummary {
    std::size_t points = 0, done = 0;
    std::vector<std::pair<std::string, double>> best;
    bool running = false;
};
SweepSummary sweep_summary(const LabSession& s);
// Preset files (ui/preset_files.cpp). The user's own presets: $XDG_DATA_HOME/particle-lab/presets,
// default ~/.local/share/particle-lab/presets.
std::filesystem::path user_preset_dir();
// Whether `file` is one of the shipped presets (in s.preset_dir), which are never written.
bool is_shipped_preset(const LabSession& s, const std::filesystem::path& file);
// The file dialog, to save a copy (then `then`, e.g. the quit that asked to save first), to open
// a preset, or to choose the folder plot exports go to. draw_file_dialogs shows it and acts.
void begin_save_as(LabSession& s, std::optional<PendingAction> then);
void begin_open(LabSession& s);
void begin_choose_export_folder(LabSession& s);
// Saves before `then` ("Save and quit"): in place, or for a shipped preset or a scene without a
// file through Save As, which performs `then` once saved. True when saved in place.
bool save_then(LabSession& s, const PendingAction& then);
void draw_file_dialogs(LabSession& s);

}  // namespace pl::ui
