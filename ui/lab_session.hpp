// LabSession: everything the GUI shows and edits, owned by the app shell and passed to the
// panels. The panels (ui/) read and edit physics data; they never step physics themselves,
// except through the session's requests, which the app shell executes between frames.
#pragma once

#include "physics/stepping/experiment.hpp"
#include "io/preset_io.hpp"
#include "physics/model/scene.hpp"

#include <array>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace pl::ui {

struct PlotHistory;  // ui/plot_history.hpp: bounded per-series sample buffers
struct PanelState;   // ui/panel_state.hpp: what the panels remember between frames
struct PinBoard;     // ui/pinned_runs.hpp: runs kept beside the live one
struct WarningTally; // ui/lab_ui.cpp: warnings and notes counted so far, per variant

// What the shell measured this frame (shown in the status bar).
struct FrameStats {
    double fps = 0.0;
    double physics_ms = 0.0;       // time spent stepping since the last frame (the physics thread's, or this frame's)
    double render_ms = 0.0;        // the last frame's own work: panels, drawing, presenting (not waits or sleeps)
    std::uint64_t substeps = 0;    // base steps run this frame
    bool behind = false;           // physics could not keep up with real time
    double real_time_factor = 0.0; // simulated seconds per real second, smoothed
};

// Requests the panels raise; the shell performs them at a safe point of the frame.
struct Requests {
    bool reset = false;
    bool single_step = false;
    bool run_to_next_event = false;
    bool relaunch = false;           // L: launch particle 0 again with launch_velocity
    bool screenshot = false;
    std::filesystem::path screenshot_path;
    // When crop_w > 0 the screenshot keeps only this rectangle, in ImGui display coordinates
    // (origin top left; the shell scales by the framebuffer scale). Used to export one plot.
    float crop_x = 0.0f, crop_y = 0.0f, crop_w = 0.0f, crop_h = 0.0f;
    bool quit = false;
};

// A request that would replace the scene or end the app. With unsaved edits it waits in
// LabSession::pending until the user answers the unsaved-changes dialog (ui/unsaved_prompt.cpp).
struct PendingAction {
    enum class Kind { quit, open, revert };
    Kind kind = Kind::quit;
    std::filesystem::path file;  // open, revert: the preset to load
};

// A point the measuring tool picked in the 3D view: a trail sample or a ball where it is now.
struct MeasuredPoint {
    Vec3 position{0.0, 0.0, 0.0};
    double t = 0.0;  // simulated time of the sample, s
    std::size_t variant = 0, particle = 0;
};

// Particle 0 of a scene as it starts (the explicit list's first, else the emitter's); none
// without particles.
std::optional<ParticleSpec> first_particle(const Scene& scene);

struct LabSession {
    Scene scene;                               // what the user edits (the preset)
    std::unique_ptr<Experiment> experiment;    // running instance built from `scene`
    std::filesystem::path preset_path;         // file the scene came from / is saved to
    bool dirty = false;                        // unsaved edits
    bool paused = false;
    double time_scale = 1.0;
    int selected_particle = 0;
    int selected_variant = 0;
    Vec3 launch_velocity{3.0, 4.0, 1.0};       // the L key / launch tool; a preset sets its particle 0's
    std::string error_popup;                   // non-empty: shown in a modal, scene untouched
    std::string status_message;                // transient one-line message
    Requests requests;
    FrameStats frame;
    std::shared_ptr<PlotHistory> history;      // created by the ui on first use
    std::shared_ptr<PanelState> panels;        // created by the ui on first use
    std::shared_ptr<PinBoard> pins;            // created by the ui on first pin; survives loads and edits
    // A cache of warning_count / note_count (counting reads every warning's drag model, and a
    // large scene has one warning per particle): only warnings raised since the last count are read.
    mutable std::shared_ptr<WarningTally> warning_tally;
    std::filesystem::path preset_dir;          // shipped presets (the shell finds them: app/data_dir.hpp)

    // 3D view options (the shell's view toolbar edits them; panels may too).
    bool show_trails = true;
    int trail_particles = 16;                  // trails (and drop lines) for the first N particles of each variant
    bool show_velocity = false;                // velocity arrows on the particles
    bool show_wind = false;                    // wind field arrows on a grid
    bool show_contacts = false;                // collision contacts as lines, coloured by their load
    bool tint_sleeping = false;                // sleeping particles (collisions' islands at rest) in a slate tint
    bool split_view = false;                   // one viewport per variant (up to 9) instead of overlaid
    std::vector<int> split_variants;           // the variants the split view shows (empty: the first 9)
    bool measuring = false;                    // M: clicks in the view pick points to measure between
    std::vector<MeasuredPoint> measure_points; // 0, 1 or 2; a third click starts again; Esc clears
    // Popups the shell toggles from keys and window events; draw_popups shows them.
    bool show_help = false;                    // F1/H toggle, Esc closes
    std::optional<PendingAction> pending;      // asked about: unsaved edits would be lost (Save / Discard / Cancel)
    // Screen rectangles {x, y, w, h} of a few named widgets as the last frame drew them (only
    // while visible), for the GUI tests to click: "tab.warnings", "warnings.row0", "preset.NAME".
    std::map<std::string, std::array<float, 4>> widget_rects;

    // Every path that drops the scene (Ctrl+O, Load, Revert, Ctrl+Q, closing the window) comes
    // here: done at once when nothing is unsaved, otherwise left in `pending` for the dialog.
    void request(const PendingAction& a);
    // Does `a` now (no question asked); false when a load failed (the error dialog says why).
    bool perform(const PendingAction& a);
    // Replaces the scene and rebuilds the experiment; on failure nothing changes.
    bool load(const std::filesystem::path& file);
    // A preset opened from `file`: the scene, and the launch it defines (particle 0's velocity
    // becomes the Launch panel's, so L throws what the preset throws). Empty, or why the scene
    // cannot run here (apply_scene), nothing changed.
    std::string open_preset(const Scene& s, const std::filesystem::path& file);
    // Rebuilds the experiment from an edited scene. A scene whose state would not fit in the
    // memory available (physics/studies/resource_estimate.hpp), or whose building throws
    // bad_alloc or length_error, is refused: the returned text says why (with the numbers), and
    // the current scene and run are kept.
    std::string apply_scene(const Scene& s);
};

}  // namespace pl::ui
