#include "app/shortcuts.hpp"

#include "ui/lab_ui.hpp"
#include "ui/pinned_runs.hpp"

#include <GLFW/glfw3.h>

namespace pl::app {

namespace {

void close_popups(ui::LabSession& s) {
    s.show_help = false;
    s.pending.reset();
    s.error_popup.clear();
    s.measure_points.clear();
}

}  // namespace

ViewCommand apply_shortcuts(const std::vector<KeyPress>& keys, bool text_input_active, bool keyboard_captured,
                            ui::LabSession& s) {
    ViewCommand view;
    for (const KeyPress& k : keys) {
        if (text_input_active) continue;  // typing into a field: every key belongs to it
        if (k.key == GLFW_KEY_ESCAPE) {
            close_popups(s);
            view.cancel_gesture = true;
            continue;
        }
        if ((k.mods & GLFW_MOD_CONTROL) && k.key == GLFW_KEY_Q) {
            s.request({ui::PendingAction::Kind::quit, {}});
            continue;
        }
        if ((k.mods & GLFW_MOD_CONTROL) && k.key == GLFW_KEY_S) {
            ui::save_in_place(s);
            continue;
        }
        if ((k.mods & GLFW_MOD_CONTROL) && k.key == GLFW_KEY_O) {
            ui::focus_open_path(s);
            continue;
        }
        if (keyboard_captured || (k.mods & (GLFW_MOD_CONTROL | GLFW_MOD_ALT | GLFW_MOD_SUPER))) continue;
        const bool shift = k.mods & GLFW_MOD_SHIFT;
        switch (k.key) {
            case GLFW_KEY_SPACE: s.paused = !s.paused; break;
            case GLFW_KEY_R: s.requests.reset = true; break;
            case GLFW_KEY_N: s.requests.single_step = true; break;
            case GLFW_KEY_L: s.requests.relaunch = true; break;
            case GLFW_KEY_P: s.status_message = ui::pin_current_run(s); break;
            case GLFW_KEY_M:
                s.measuring = !s.measuring;
                s.measure_points.clear();
                break;
            case GLFW_KEY_F1:
            case GLFW_KEY_H: s.show_help = !s.show_help; break;
            case GLFW_KEY_F: view.focus_selected = true; break;
            case GLFW_KEY_F9: view.toggle_recording = true; break;
            case GLFW_KEY_1: case GLFW_KEY_KP_1: view.axis = 0; view.from_negative = shift; break;
            case GLFW_KEY_2: case GLFW_KEY_KP_2: view.axis = 1; view.from_negative = shift; break;
            case GLFW_KEY_3: case GLFW_KEY_KP_3: view.axis = 2; view.from_negative = shift; break;
            case GLFW_KEY_0: case GLFW_KEY_KP_0: view.reset = true; break;
            default: break;
        }
    }
    return view;
}

}  // namespace pl::app
