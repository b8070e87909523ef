#include "app/gui_options.hpp"

#include "app/data_dir.hpp"

#include <CLI/CLI.hpp>

#include <cstdio>

namespace pl::app {

ParsedGuiOptions parse_gui_options(int argc, char** argv) {
    CLI::App app{"particle-lab: a lab for Newtonian particle experiments (GUI). "
                 "Subcommands (run, validate, compare, ...) run headless; see `particle-lab run --help`."};
    GuiOptions o;
    std::string preset;
    long frames = 0;
    std::string screenshot, dump_state;
    double time_scale = 1.0, fixed_dt = 0.0, max_fps = 0.0;
    app.add_option("preset", preset, "Preset JSON to open (default: presets/default.json in the data folder)");
    auto* frames_opt = app.add_option("--frames", frames, "Exit after N frames")->check(CLI::PositiveNumber);
    auto* shot_opt = app.add_option("--screenshot", screenshot, "Write a PNG of the last frame to this file");
    auto* dump_opt = app.add_option("--dump-state", dump_state, "Write the state as JSON at exit (and on SIGUSR1)");
    auto* scale_opt = app.add_option("--time-scale", time_scale, "Simulated seconds per real second")
                          ->check(CLI::Range(1e-3, 1e3));
    auto* fixed_opt = app.add_option("--fixed-frame-dt", fixed_dt,
                                     "Advance every frame by this real time in seconds (deterministic runs)")
                          ->check(CLI::Range(1e-6, 1.0));
    auto* max_fps_opt = app.add_option("--max-fps", max_fps,
                                       "Draw at most N frames per second (default 120); physics runs at its own pace")
                            ->check(CLI::Range(1.0, 1000.0));
    RecordSettings record;
    std::string record_file, record_area = "window";
    double record_seconds = 0.0;
    auto* record_opt =
        app.add_option("--record", record_file, "Record a video (.mp4 H.264, .webm VP9) or .gif through ffmpeg, then exit");
    app.add_option("--record-seconds", record_seconds, "Seconds of video to record (simulated time / the time scale)")
        ->check(CLI::Range(1e-3, 3600.0))
        ->needs(record_opt);
    record_opt->needs("--record-seconds");
    app.add_option("--record-fps", record.fps, "Frames per second of the recording; each advances the simulation by 1/fps s")
        ->check(CLI::Range(min_record_fps, max_record_fps))
        ->needs(record_opt);
    std::vector<std::string> area_names;
    for (const RecordAreaName& a : record_areas()) area_names.push_back(a.name);
    app.add_option("--record-area", record_area, "Part of the window to record (default window)")
        ->check(CLI::IsMember(area_names))
        ->needs(record_opt);
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
    if (*max_fps_opt) o.max_fps = max_fps;
    if (*record_opt) {
        if (const std::string bad = check_record_file(record_file, "--record"); !bad.empty()) {
            std::fprintf(stderr, "particle-lab: %s\n", bad.c_str());
            return {std::nullopt, 2};
        }
        record.file = record_file;
        record.seconds = record_seconds;
        record.area = *parse_record_area(record_area);
        o.record = record;
    }
    return {o, 0};
}

}  // namespace pl::app
