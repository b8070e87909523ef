// The measuring tool (key M or the view toolbar's "Measure"): while it is on, a click in the 3D
// view picks the trail sample or ball nearest the cursor on screen (within snap_radius_px), and
// two picks read the distance and the simulated time between them in an overlay. A third click
// starts a new measurement; Esc clears it.
#pragma once

#include "app/camera.hpp"
#include "app/trail_history.hpp"
#include "app/view_panes.hpp"
#include "ui/lab_session.hpp"

#include <optional>
#include <vector>

namespace pl::app {

constexpr float snap_radius_px = 24.0f;
constexpr float ball_snap_px = 8.0f;  // a ball this near the cursor wins over trail samples

// The trail sample or ball (now) whose screen position is nearest (mx, my) in the pane under
// it, if one lies within snap_radius_px.
std::optional<ui::MeasuredPoint> snap_measure_point(const ui::LabSession& s, const TrailHistory& trails,
                                                    const std::vector<ViewPane>& panes, const OrbitCamera& camera,
                                                    float mx, float my);

// A click in the view while measuring: adds the snapped point (a third starts over).
void measure_click(ui::LabSession& s, const TrailHistory& trails, const std::vector<ViewPane>& panes,
                   const OrbitCamera& camera, float mx, float my);

// The points, the line between them and "distance, time" beside it; a hint while measuring.
void draw_measure_overlay(const ui::LabSession& s, const std::vector<ViewPane>& panes, const OrbitCamera& camera);

}  // namespace pl::app
