// What is drawn over the 3D view with ImGui: metre labels on the floor edges and a height scale,
// the axis gizmo, pane labels or the variant legend, time and pause state, selection and hover
// rings.
#pragma once

#include "app/camera.hpp"
#include "app/picking.hpp"
#include "app/view_panes.hpp"
#include "ui/lab_session.hpp"

#include <optional>
#include <vector>

namespace pl::app {

struct HoveredParticle {
    ParticleRef particle;
    std::size_t pane = 0;
};

void draw_view_overlay(const ui::LabSession& session, const std::vector<ViewPane>& panes, const OrbitCamera& camera,
                       const std::optional<HoveredParticle>& hovered);

}  // namespace pl::app
