// Mouse and keyboard on the 3D view: left-drag orbits, right/middle-drag (or Shift+left) pans,
// the wheel zooms, a click selects the particle under the cursor, Ctrl+left-drag aims and
// launches a particle (app/launch_gesture.hpp); WASD + Q/E fly the camera and the arrow keys
// orbit it. The mouse acts only over the view, never through a panel.
#pragma once

#include "app/camera.hpp"
#include "app/input_events.hpp"
#include "app/launch_gesture.hpp"
#include "app/view_overlay.hpp"
#include "app/view_panes.hpp"
#include "ui/lab_session.hpp"

#include <optional>
#include <vector>

struct GLFWwindow;

namespace pl::app {

struct ViewDrag {
    int button = -1;        // mouse button held since a press over the view, -1 none
    float press_x = 0, press_y = 0;
    bool moved = false;     // beyond the click tolerance: a drag, not a click
    bool aiming = false;    // a left drag that began with Ctrl: launch aim, the camera stays
    LaunchAim aim;          // active until released (launch) or cancelled (Esc, right-click)
    bool clicked = false;   // this frame: a left click (no drag) over the view ended at (press_x, press_y)
};

// Updates the camera from the mouse; returns the particle under the cursor, and selects it in
// `session` on a click (not while the measuring tool is on: the click is its, drag.clicked). A Ctrl+left drag aims instead and launches on release.
std::optional<HoveredParticle> handle_view_mouse(ViewDrag& drag, OrbitCamera& camera, const std::vector<ViewPane>& panes,
                                                 ui::LabSession& session);

// Held keys move the camera (call once per frame with the real frame time); keys that are part
// of a shortcut chord (`input.chorded`) do not.
void handle_view_keys(GLFWwindow* window, const InputQueue& input, OrbitCamera& camera, float real_dt);

}  // namespace pl::app
