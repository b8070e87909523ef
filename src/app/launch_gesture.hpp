// Aiming a launch by dragging in the 3D view (Ctrl + left drag). The arrow runs from the particle
// to the point under the cursor on the plane through the particle facing the camera; its length
// is the straight path the particle would cover in aim_arrow_time_s (1 s in a 10 m room, so one
// metre of arrow is one m/s against the floor grid), and the launch velocity is
// (tip - particle) / that time. On release the particle gets this velocity where it is, through
// the same kick as the Launch section's "Kick selected".
#pragma once

#include "app/camera.hpp"
#include "app/view_panes.hpp"
#include "ui/lab_session.hpp"
#include "ui/launch_angles.hpp"

#include <optional>
#include <vector>

namespace pl::app {

struct LaunchAim {
    bool active = false;
    std::size_t pane = 0;           // the pane the drag started in
    std::size_t variant = 0;        // the particle the arrow starts from
    std::size_t particle = 0;
    Vec3 velocity{0.0};             // what a release now would launch with
    bool clamped = false;           // the drag asked for more than ui::max_launch_speed_mps
    float cursor_x = 0.0f, cursor_y = 0.0f;
};

// The 1-2-5 time (s) at or below the room's largest size / 10 m/s: a throw at 10 m/s draws an
// arrow as long as the room whatever its scale.
double aim_arrow_time_s(const Room& room);

// The velocity that carries a particle at `anchor` to the cursor's point on the plane through
// `anchor` facing the camera in `arrow_time_s`, clamped to ui::max_launch_speed_mps (`clamped` says so).
// Empty when the cursor ray misses that plane.
std::optional<Vec3> aim_velocity(const OrbitCamera& camera, const Rect& pane, float mouse_x, float mouse_y,
                                 const Vec3& anchor, double arrow_time_s, bool& clamped);

// Starts aiming at the particle under the cursor (it becomes the selection), else at the
// selected particle, else particle 0. Returns false (and stays inactive) when there is nothing
// to aim or the particle is behind the camera.
bool begin_launch_aim(LaunchAim& aim, ui::LabSession& session, const std::vector<ViewPane>& panes, std::size_t pane,
                      const OrbitCamera& camera, float mouse_x, float mouse_y);
// Follows the cursor; cancels when the particle or the pane is gone (a preset was loaded).
void update_launch_aim(LaunchAim& aim, const ui::LabSession& session, const std::vector<ViewPane>& panes,
                       const OrbitCamera& camera, float mouse_x, float mouse_y);
// Kicks the particle (every variant's particle of that index) with the aimed velocity, makes it
// the Launch section's velocity too (so L throws it again), and ends the aim.
void finish_launch_aim(LaunchAim& aim, ui::LabSession& session);
inline void cancel_launch_aim(LaunchAim& aim) { aim.active = false; }

// The aim arrow, its shadow on the floor, and the speed, elevation and azimuth next to the cursor.
void draw_launch_aim(const LaunchAim& aim, const ui::LabSession& session, const std::vector<ViewPane>& panes,
                     const OrbitCamera& camera);

}  // namespace pl::app
