// Pinned runs: copies of a finished or running run kept beside the live one, so a change can be
// compared with what came before ("change it, throw again, compare"). A pin holds the selected
// variant's plot series (thinned), its particles' paths (the 3D view's ghosts) and its live
// metrics; edits, relaunches and resets start a new live run and leave the pins alone.
#pragma once

#include "physics/studies/metrics.hpp"
#include "ui/palette.hpp"
#include "ui/plot_history.hpp"

#include <optional>
#include <string>
#include <vector>

namespace pl::ui {

struct LabSession;

// One named setting of a run, e.g. {"Cd", "0.6"}: what a pin's label is made of.
struct RunSetting {
    std::string name, value;
};

// The settings that tell runs of one scene apart: the model's drag, wind, air, contact and
// integrator, and particle 0's mass, radius, start and launch velocity. The one list that both
// labels and differences read.
std::vector<RunSetting> run_settings(const Model& m, const ParticleSpec& particle0, const Vec3& launch_velocity);

// "Cd 0.6, dt 0.01": the settings of `now` whose value differs from `before` (or that `before`
// lacks), at most `max_shown` of them and then "...". Empty when nothing differs.
std::string settings_difference(const std::vector<RunSetting>& before, const std::vector<RunSetting>& now,
                                std::size_t max_shown = 3);

struct PinnedRun {
    int number = 0;                    // "run N", counting every pin of the session
    std::string label;                 // "run 2: Cd 0.6"
    std::vector<RunSetting> settings;
    double t_end = 0.0;                // simulated time when it was pinned
    std::vector<ParticleTrack> particles;  // thinned to at most max_samples per series
    AggregateTrack aggregate;
    std::vector<PathSeries> paths;
    std::optional<VariantMetrics> metrics;  // live metrics, when the scene had them
};

struct PinBoard {
    static constexpr std::size_t max_pins = 12;       // pinning one more lets the oldest go
    static constexpr std::size_t max_samples = 4096;  // per series of a pin: memory stays small
    std::vector<PinnedRun> runs;                      // oldest first
    int next_number = 1;
};

PinBoard& pins_of(LabSession& s);
const PinBoard* pins_if_any(const LabSession& s);
// Pins the selected variant of the live run; returns the status line that says what happened.
std::string pin_current_run(LabSession& s);
void unpin(LabSession& s, int number);
void clear_pins(LabSession& s);
// Pins draw in hues of their own (past the ten series colours), faded.
Rgba pin_color(int number, float alpha = 0.6f);

}  // namespace pl::ui
