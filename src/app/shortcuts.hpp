// The lab's keys (when no text field has the keyboard): space play/pause, R reset, N single
// step, L launch again, F1/H help, Esc closes popups and cancels a launch aim, Ctrl+Q quit,
// Ctrl+S save, Ctrl+O type a preset path to open; 1/2/3 views along x/y/z (Shift: from the other
// side), 0 reset view, F focus the selected particle, F9 start or stop recording.
#pragma once

#include "app/input_events.hpp"
#include "ui/lab_session.hpp"

#include <optional>

namespace pl::app {

struct ViewCommand {
    std::optional<int> axis;  // look along this world axis
    bool from_negative = false;
    bool reset = false;
    bool focus_selected = false;
    bool cancel_gesture = false;  // Esc: drop a launch aim in progress
    bool toggle_recording = false;  // F9 or the REC button (app/record_controls.hpp)
};

// Applies session-level keys to `session`; returns the camera commands.
ViewCommand apply_shortcuts(const std::vector<KeyPress>& keys, bool text_input_active, bool keyboard_captured,
                            ui::LabSession& session);

}  // namespace pl::app
