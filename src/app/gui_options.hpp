// Command line of the GUI: particle-lab [PRESET] [--frames N] [--screenshot out.png]
// [--dump-state path] [--time-scale S] [--fixed-frame-dt SECONDS] [--max-fps N]
// [--record out.mp4|out.webm|out.gif --record-seconds S [--record-fps N] [--record-area AREA]].
#pragma once

#include "app/recording.hpp"

#include <filesystem>
#include <optional>
#include <string>

namespace pl::app {

struct GuiOptions {
    std::filesystem::path preset;             // default: presets/default.json
    std::optional<long> frames;               // exit after this many frames
    std::optional<std::filesystem::path> screenshot;  // PNG of the last frame
    std::optional<std::filesystem::path> dump_state;  // JSON state at exit (and on SIGUSR1)
    std::optional<double> time_scale;         // simulated seconds per real second
    std::optional<double> fixed_frame_dt;     // every frame advances by this real time (tests)
    std::optional<double> max_fps;            // draw at most this many frames per second (default 120)
    std::optional<RecordSettings> record;     // record from the first frame, then exit
};

struct ParsedGuiOptions {
    std::optional<GuiOptions> options;  // absent: exit with exit_code (help shown or bad input)
    int exit_code = 0;
};

ParsedGuiOptions parse_gui_options(int argc, char** argv);

}  // namespace pl::app
