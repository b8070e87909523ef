// Orbit camera around a target point: yaw about +y, pitch above the horizon, distance.
#pragma once

#include "physics/model/scene.hpp"

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace pl::app {

struct OrbitCamera {
    glm::vec3 target{0.0f};
    float yaw = 0.0f;       // rad; 0 looks along -z (from +z)
    float pitch = 0.3f;     // rad; > 0 looks down on the target
    float distance = 10.0f; // m
    float fov_y = 0.785398f;  // rad (45 degrees)
};

struct CameraMatrices {
    glm::mat4 view{1.0f}, proj{1.0f}, view_proj{1.0f};
    glm::vec3 eye{0.0f};
    glm::vec3 forward{0.0f, 0.0f, -1.0f};
};

// Unit vectors of the camera frame (world space). Valid at any pitch, including straight down.
glm::vec3 camera_forward(const OrbitCamera& c);
glm::vec3 camera_right(const OrbitCamera& c);
glm::vec3 camera_up(const OrbitCamera& c);
glm::vec3 camera_eye(const OrbitCamera& c);
CameraMatrices camera_matrices(const OrbitCamera& c, float aspect);
// Size in metres of one pixel at one metre from the camera, in a viewport `height_px` tall.
float pixel_size_at_unit_depth(const OrbitCamera& c, float height_px);

// Three-quarter view from above that shows the whole room.
OrbitCamera framing_camera(const Room& room);
// Looking along a world axis (0 = x, 1 = y, 2 = z) at the whole room; from the + side unless
// `from_negative`.
OrbitCamera axis_camera(const Room& room, int axis, bool from_negative);

void orbit(OrbitCamera& c, float delta_yaw, float delta_pitch);
// Moves the target so the scene follows a mouse drag of `pixels` in a viewport `height` tall.
void pan(OrbitCamera& c, glm::vec2 pixels, float viewport_height);
// Wheel steps: > 0 moves closer.
void zoom(OrbitCamera& c, float wheel_steps);
// Keyboard fly (the seed's WASD + Q/E): `move` in camera axes (right, up, forward), -1..1 each.
void fly(OrbitCamera& c, glm::vec3 move, float real_dt);

}  // namespace pl::app
