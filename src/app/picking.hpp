// Which particle is under the mouse: a ray from the camera through the cursor against every
// particle's sphere (slightly enlarged when small on screen so it stays easy to hit).
#pragma once

#include "app/camera.hpp"
#include "app/layout.hpp"
#include "physics/stepping/experiment.hpp"

#include <optional>

namespace pl::app {

struct ParticleRef {
    std::size_t variant = 0, particle = 0;
};

struct Ray {
    glm::vec3 origin, direction;  // direction is unit length
};

Ray ray_through(const CameraMatrices& camera, const Rect& pane, float mouse_x, float mouse_y);

// `min_pick_radius_px`: spheres smaller than this on screen are picked as if this large.
std::optional<ParticleRef> pick_particle(const Experiment& e, std::optional<std::size_t> only_variant, const Ray& ray,
                                         const OrbitCamera& camera, float pane_height_px, float min_pick_radius_px = 6.0f);

// Screen position (ImGui coordinates) of a world point in a pane; empty behind the camera.
struct ScreenPoint {
    float x, y;
    float depth;  // distance along the view axis, m
};
std::optional<ScreenPoint> project(const CameraMatrices& camera, const Rect& pane, glm::vec3 world);

}  // namespace pl::app
