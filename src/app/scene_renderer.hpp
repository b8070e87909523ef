// Draws the 3D view: every pane into its own part of the window (glViewport + glScissor),
// before ImGui draws the panels around it.
#pragma once

#include "app/camera.hpp"
#include "app/renderer_background.hpp"
#include "app/renderer_instances.hpp"
#include "app/renderer_lines.hpp"
#include "app/renderer_points.hpp"
#include "app/renderer_room.hpp"
#include "app/renderer_shadows.hpp"
#include "app/renderer_spheres.hpp"
#include "app/trail_history.hpp"
#include "app/view_panes.hpp"
#include "ui/lab_session.hpp"

#include <vector>

namespace pl::app {

// Beyond this many particles in a pane, point sprites replace the instanced meshes.
constexpr std::size_t max_mesh_spheres = 10'000;
// Particles smaller than this on screen are drawn this large (radius, pixels), so none vanishes.
constexpr float min_sphere_radius_px = 3.5f;

struct FramebufferMapping {
    float scale_x = 1.0f, scale_y = 1.0f;  // framebuffer pixels per ImGui unit
    int height = 0;                        // framebuffer height in pixels
};

class SceneRenderer {
public:
    SceneRenderer();
    void draw(const ui::LabSession& session, const TrailHistory& trails, const std::vector<ViewPane>& panes,
              const OrbitCamera& camera, const FramebufferMapping& fb);

private:
    void draw_pane(const ui::LabSession& session, const TrailHistory& trails, const ViewPane& pane,
                   const OrbitCamera& camera, const FramebufferMapping& fb);
    void draw_contacts(const Experiment& e, const ViewPane& pane, const CameraMatrices& cam, glm::vec2 viewport);

    InstanceBuffer instances_;
    SphereRenderer spheres_;
    PointSpriteRenderer points_;
    ShadowRenderer shadows_;
    LineRenderer lines_;
    RoomRenderer room_;
    BackgroundRenderer background_;
    std::vector<SphereInstance> instance_scratch_;
    LineSegments segments_;
};

}  // namespace pl::app
