// What the panels remember between frames (LabSession::panels): view settings, edits in
// progress, and the background studies.
#pragma once

#include "io/sweep_view.hpp"
#include "physics/studies/accuracy_study.hpp"
#include "physics/studies/advisor.hpp"
#include "physics/studies/metrics.hpp"
#include "physics/studies/stability_study.hpp"
#include "ui/background_job.hpp"
#include "ui/field_edit.hpp"
#include "ui/file_dialog.hpp"
#include "ui/lab_session.hpp"
#include "ui/plot.hpp"

#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace pl::ui {

struct PresetEntry {
    std::filesystem::path path;
    std::string name;  // file stem
    bool shipped = false;
};

// A plot picture waits a frame or two so the menu that asked for it is gone from the screen.
struct PendingPicture {
    int frames_left = -1;  // < 0: none
    std::filesystem::path path;
    ImVec2 min, max;
};

// Exports held back because their file exists, until the user answers Overwrite / Cancel.
struct PendingExports {
    std::vector<std::pair<std::filesystem::path, std::string>> csv;  // file, text
    std::optional<PendingPicture> picture;
};

struct StabilitySettings {
    Method method = Method::semi_implicit_euler;
    std::vector<double> dts, stiffnesses;
};

struct StabilityMap {
    StabilitySettings settings;
    std::vector<StabilityCell> cells;  // dts outer, stiffnesses inner
    std::vector<StabilityLimit> limits;
    std::vector<StabilityCell> pair_cells;  // the study's collision slice for the method
    bool cancelled = false;
};

// A sweep the Sweep tab ran: what it ran (spec, prepared scenes) and what came out.
struct SweepRun {
    SweepSpec spec;
    PreparedSweep prepared;
    SweepResults results;
    std::string error;  // a refused plan or point: nothing ran
};

struct PanelState {
    // ---- plots
    plot::TimeAxisLink time_axis;
    std::set<std::string> hidden_series;
    bool show_event_markers = true;
    int plots_tab = 0;
    std::string export_stem = "particle-lab";  // files go to <export_dir>/<stem>-<plot>.csv/.png
    std::filesystem::path export_dir;          // chosen in the file dialog; empty: the working directory
    PendingPicture picture;
    PendingExports export_question;  // ui/export_question.cpp

    // ---- control panel
    FieldEdits fields;
    const void* edits_experiment = nullptr;  // refused edits are dropped when the scene is replaced
    std::vector<PresetEntry> presets;
    bool presets_scanned = false;
    int preset_choice = -1;
    FileDialog file_dialog;                  // one at a time: open, save as, export folder
    std::optional<PendingAction> after_save; // "Save and quit" on a shipped preset: quit once saved
    std::string open_path;
    bool focus_open_path = false;      // Ctrl+O: the next frame puts the keyboard in the open-path field
    double launch_speed = 0.0, launch_elevation_deg = 0.0, launch_azimuth_deg = 0.0;
    bool launch_from_velocity = true;  // derive the three from session.launch_velocity once
    std::unordered_map<ImGuiID, std::string> text_buffers;  // text fields (name, labels) being typed
    ImGuiID text_editing = 0;

    // ---- analysis
    int baseline_variant = 0;
    int compare_mode = 0;  // 0: live, 1: timed run
    bool compare_differences = false;
    bool events_follow = true;
    int events_variant_filter = -1;  // -1: all
    BackgroundJob<Comparison> timed_compare;
    double timed_compare_duration_s = 5.0;
    BackgroundJob<AccuracyReport> accuracy;
    double accuracy_duration_s = 2.0;
    int accuracy_view = 0;        // 0: diagram, 1: table
    bool accuracy_window = false; // the diagram also in a window of its own
    int stability_view = 0;       // 0: map, 1: limits table, 2: collision slice
    bool stability_window = false;
    int accuracy_cost_axis = 0;   // 0: force evaluations, 1: wall time per simulated second
    int accuracy_error_axis = 0;  // 0: position, 1: velocity, 2: bounce time
    const void* accuracy_experiment = nullptr;  // the experiment the study was started on
    BackgroundJob<StabilityMap> stability;
    BackgroundJob<Advice> advice;
    double advice_tolerance_m = 1e-3;    // AdviceOptions' tolerances
    double advice_tolerance_s = 1e-3;
    double advice_tolerance_mps = 1e-3;
    const void* advice_experiment = nullptr;
    BackgroundJob<SweepRun> sweep;
    SweepChoices sweep_choices = [] {
        SweepChoices c;
        c.first.count = 15;  // 5 degree steps: the drag-free optimum, 45, is on the grid
        c.second.path = "drag.model";
        c.second.list = true;
        c.second.values = "none,linear,quadratic,sphere_re";
        return c;
    }();
    int sweep_metric = 1;  // range_at_first_impact_m
};

PanelState& panels_of(LabSession& s);

}  // namespace pl::ui
