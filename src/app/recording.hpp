// Recording a run as a video or GIF on the fixed simulated clock: while recording, every frame
// stands for exactly 1/fps real seconds (x the time scale in simulated time) whatever the
// display's frame rate, so a recording is smooth and the same preset records the same frames.
// The frames (the whole window or a chosen area of it) go to ffmpeg (app/video_pipe.hpp).
#pragma once

#include "app/layout.hpp"
#include "app/screenshot.hpp"
#include "app/video_pipe.hpp"

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace pl::app {

enum class RecordArea { window, view, plots, view_and_plots };

struct RecordAreaName {
    RecordArea area;
    const char* name;   // on the command line: --record-area NAME
    const char* label;  // in the GUI
};
const std::vector<RecordAreaName>& record_areas();
std::optional<RecordArea> parse_record_area(const std::string& name);

// The area in ImGui coordinates (window pixels) for this frame's layout.
Rect record_rect(RecordArea area, const ShellLayout& layout, float display_w, float display_h);

struct RecordSettings {
    std::filesystem::path file;
    int fps = 30;
    RecordArea area = RecordArea::window;
    std::optional<double> seconds;  // stop after seconds*fps frames; none: until stopped
};

constexpr int min_record_fps = 1, max_record_fps = 120;

// "" when `file` may be recorded to, otherwise why not (naming `what`): it must have a video
// extension and must not lie in the shipped data folder.
std::string check_record_file(const std::filesystem::path& file, const std::string& what);

class Recorder {
public:
    bool active() const { return pipe_.is_open(); }
    // Starts ffmpeg for `area` (framebuffer pixels; trimmed to even sizes for the codecs).
    std::string start(const RecordSettings& settings, PixelRect area);
    // The real time this frame's physics must advance by: 1/fps while recording.
    std::optional<double> frame_dt() const;
    // Sends the back buffer's area (after drawing, before the swap). Returns "" or why the
    // recording failed (it is then cancelled).
    std::string capture(int framebuffer_width, int framebuffer_height);
    // Whether the settings' seconds have been recorded.
    bool done() const;
    // Finishes the file. Returns "" or why it failed.
    std::string stop();

    long frames() const { return frames_; }
    const RecordSettings& settings() const { return settings_; }

private:
    RecordSettings settings_;
    PixelRect area_;
    VideoPipe pipe_;
    std::vector<unsigned char> pixels_;
    long frames_ = 0;
};

// A default file for a GUI recording: PRESET-YYYYmmdd-HHMMSS.EXT in $XDG_VIDEOS_DIR, else
// ~/Videos when it exists, else the working directory; never an existing file.
std::filesystem::path default_record_file(const std::string& preset_name, const char* extension);

}  // namespace pl::app
