// The GUI side of recording: the toolbar's REC button (its popup chooses the file, format, area
// and frame rate; while recording it turns into a red "REC 2.3 s" stop button), F9 to start or
// stop, and the hooks the frame loop calls around each frame.
#pragma once

#include "app/layout.hpp"
#include "app/recording.hpp"
#include "ui/lab_session.hpp"

#include <filesystem>
#include <string>

namespace pl::app {

struct RecordControl {
    Recorder recorder;
    RecordSettings next;             // what the next recording uses (the popup edits it)
    bool toggle = false;             // F9 or the button: start or stop at the next frame's start
    bool quit_when_done = false;     // --record: the app exits once the seconds are recorded
    std::filesystem::path last_file; // the last finished recording
    std::string error;               // why the last recording failed, if it did
};

// Before the frame's physics: starts or stops a recording the user asked for. `layout` and the
// framebuffer scale place the chosen area.
void begin_record_frame(RecordControl& rec, ui::LabSession& s, const ShellLayout& layout, float display_w,
                        float display_h, float scale_x, float scale_y);

// After drawing, before the swap: sends the frame and finishes the recording when its seconds are
// done. Returns true when the app should exit (a --record run is complete or failed).
bool end_record_frame(RecordControl& rec, ui::LabSession& s, int framebuffer_w, int framebuffer_h);

// Stops a recording still running (at exit), keeping what was recorded.
void finish_recording(RecordControl& rec, ui::LabSession& s);

// The toolbar's REC / stop button and its settings popup.
void draw_record_controls(RecordControl& rec, ui::LabSession& s);

}  // namespace pl::app
