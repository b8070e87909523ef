#include "ui/pin_scene.hpp"

#include "ui/lab_ui.hpp"
#include "ui/pinned_runs.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace pl::ui {

std::string pin_scene(LabSession& s, const Scene& scene, double duration_s, const std::string& what) {
    // A session of its own shares only the pin board: the live scene, its history, its edits
    // and its selection stay untouched.
    LabSession run;
    run.pins = s.pins ? s.pins : (s.pins = std::make_shared<PinBoard>());
    if (const std::string refused = run.apply_scene(scene); !refused.empty()) return "Not pinned: " + refused;
    if (const std::optional<ParticleSpec> p0 = first_particle(scene)) run.launch_velocity = p0->velocity;
    Experiment& e = *run.experiment;
    const auto steps = static_cast<std::uint64_t>(std::ceil(duration_s / e.base_dt() - 1e-9));
    // Steps in the runs the recorder asks for, as the shell's after-steps hook does.
    for (std::uint64_t done = 0; done < steps;) {
        const std::uint64_t n = std::clamp<std::uint64_t>(record_step(run), 1, steps - done);
        e.step_base(n);
        done += n;
    }
    record_step(run);
    record_frame(run);
    const std::string pinned = pin_current_run(run);
    PinBoard& board = *run.pins;
    if (board.runs.empty() || pinned.rfind("Pinned", 0) != 0) return pinned;
    PinnedRun& pin = board.runs.back();
    pin.label = "run " + std::to_string(pin.number) + ": " + what;
    char ran[64];
    std::snprintf(ran, sizeof ran, " (%.3g s, %llu steps)", duration_s, static_cast<unsigned long long>(steps));
    return "Pinned " + pin.label + ran;
}

}  // namespace pl::ui
