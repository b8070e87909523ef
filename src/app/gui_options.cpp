#include "app/gui_options.hpp"

#include "app/data_dir.hpp"

#include <CLI/CLI.hpp>

namespace pl::app {

ParsedGuiOptions parse_gui_options(int argc, char** argv) {
    CLI::App app{"particle-lab: a lab for Newtonian particle experiments (GUI). "
                 "Subcommands (run, validate, compare, ...) run headless; see `particle-lab run --help`."};
    GuiOptions o;
    std::string preset;
    long frames = 0;
    std::string screenshot, dump_state;
    double time_scale = 1.0, fixed_dt = 0.0;
    app.add_option("preset", preset, "Preset JSON to open (default: presets/default.json in the data folder)");
    auto* frames_opt = app.add_option("--frames", frames, "Exit after N frames")->check(CLI::PositiveNumber);
    auto* shot_opt = app.add_option("--screenshot", screenshot, "Write a PNG of the last frame to this file");
    auto* dump_opt = app.add_option("--dump-state", dump_state, "Write the state as JSON at exit (and on SIGUSR1)");
    auto* scale_opt = app.add_option("--time-scale", time_scale, "Simulated seconds per real second")
                          ->check(CLI::Range(1e-3, 1e3));
    auto* fixed_opt = app.add_option("--fixed-frame-dt", fixed_dt,
                                     "Advance every frame by this real time in seconds (deterministic runs)")
                          ->check(CLI::Range(1e-6, 1.0));
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        const int code = app.exit(e);
        return {std::nullopt, code == 0 ? 0 : 2};
    }
    o.preset = preset.empty() ? data_path("presets") / "default.json" : std::filesystem::path(preset);
    if (*frames_opt) o.frames = frames;
    if (*shot_opt) o.screenshot = screenshot;
    if (*dump_opt) o.dump_state = dump_state;
    if (*scale_opt) o.time_scale = time_scale;
    if (*fixed_opt) o.fixed_frame_dt = fixed_dt;
    return {o, 0};
}

}  // namespace pl::app
