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
#include "app/renderer_splat.hpp"
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

// A frame of the 3D view is drawn in two halves. prepare() reads the session (the physics
// thread's mutex held) into CPU buffers: particle instances, line batches, cameras. submit()
// makes the GL calls from those buffers alone, so the UI can release the mutex first: a software
// rasteriser spends milliseconds in a draw call, and the physics thread need not wait for them.
class SceneRenderer {
public:
    SceneRenderer();
    void prepare(const ui::LabSession& session, const TrailHistory& trails, const std::vector<ViewPane>& panes,
                 const OrbitCamera& camera, const FramebufferMapping& fb);
    void submit();

private:
    // Lines of one width; `through_balls` ones skip the depth test (a contact's line lies inside
    // its two spheres).
    struct LineBatch {
        LineSegments segments;
        float width_px = 1.0f;
        bool through_balls = false;
    };
    // All a pane's GL calls need, read while the mutex was held.
    struct PanePlan {
        GLint x = 0, y = 0;
        GLsizei w = 0, h = 0;
        CameraMatrices cam;
        float min_radius_per_depth = 0.0f;
        Room room;
        std::vector<SphereInstance> instances;
        LineBatch floor_grid;
        std::vector<LineBatch> overlays;  // drawn after the particles, in order
        std::size_t overlay_count = 0;    // overlays in use (the vector keeps its buffers)
        glm::vec2 viewport() const { return {static_cast<float>(w), static_cast<float>(h)}; }
        bool many() const { return instances.size() > max_mesh_spheres; }
        LineSegments& add_overlay(float width_px, bool through_balls = false);
    };

    bool prepare_pane(const ui::LabSession& session, const TrailHistory& trails, const ViewPane& pane,
                      const OrbitCamera& camera, const FramebufferMapping& fb, PanePlan& plan);
    void submit_pane(const PanePlan& plan);
    void draw_lines(const LineBatch& batch, const PanePlan& plan);

    InstanceBuffer instances_;
    SphereRenderer spheres_;
    PointSpriteRenderer points_;
    ShadowRenderer shadows_;
    SplatRenderer splat_;
    bool splat_on_cpu_ = false;  // many particles splatted on the CPU (a CPU rasteriser: renderer_splat.hpp)
    LineRenderer lines_;
    RoomRenderer room_;
    BackgroundRenderer background_;
    std::vector<PanePlan> plans_;  // kept from frame to frame for their buffers' capacity
    std::size_t plan_count_ = 0;
};

}  // namespace pl::app
