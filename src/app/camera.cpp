#include "app/camera.hpp"

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace pl::app {

namespace {

constexpr float max_pitch = 1.5706f;  // just short of pi/2: straight down still has a yaw

float room_radius(const Room& room) { return 0.5f * static_cast<float>(glm::length(room.size)); }

}  // namespace

glm::vec3 camera_forward(const OrbitCamera& c) {
    return {-std::cos(c.pitch) * std::sin(c.yaw), -std::sin(c.pitch), -std::cos(c.pitch) * std::cos(c.yaw)};
}
glm::vec3 camera_right(const OrbitCamera& c) { return {std::cos(c.yaw), 0.0f, -std::sin(c.yaw)}; }
glm::vec3 camera_up(const OrbitCamera& c) { return glm::cross(camera_right(c), camera_forward(c)); }
glm::vec3 camera_eye(const OrbitCamera& c) { return c.target - c.distance * camera_forward(c); }

CameraMatrices camera_matrices(const OrbitCamera& c, float aspect) {
    CameraMatrices m;
    m.eye = camera_eye(c);
    m.forward = camera_forward(c);
    m.view = glm::lookAt(m.eye, c.target, camera_up(c));
    const float near_plane = std::max(1e-3f, 0.02f * c.distance);
    const float far_plane = 50.0f * c.distance + 10.0f;
    m.proj = glm::perspective(c.fov_y, std::max(aspect, 1e-3f), near_plane, far_plane);
    m.view_proj = m.proj * m.view;
    return m;
}

float pixel_size_at_unit_depth(const OrbitCamera& c, float height_px) {
    return 2.0f * std::tan(0.5f * c.fov_y) / std::max(height_px, 1.0f);
}

OrbitCamera framing_camera(const Room& room) {
    OrbitCamera c;
    c.target = glm::vec3(room.center) - glm::vec3(0.0f, 0.1f * static_cast<float>(room.size.y), 0.0f);
    // Mostly from the front (+z), so motion along x, the usual throwing direction, crosses the
    // screen instead of coming at the viewer.
    c.yaw = 0.32f;
    c.pitch = 0.40f;
    c.distance = 1.08f * room_radius(room) / std::sin(0.5f * c.fov_y);
    return c;
}

OrbitCamera axis_camera(const Room& room, int axis, bool from_negative) {
    OrbitCamera c;
    c.target = glm::vec3(room.center);
    const float pi = 3.14159265f;
    switch (axis) {
        case 0: c.yaw = from_negative ? -0.5f * pi : 0.5f * pi; c.pitch = 0.0f; break;
        case 1: c.yaw = 0.0f; c.pitch = from_negative ? -max_pitch : max_pitch; break;
        default: c.yaw = from_negative ? pi : 0.0f; c.pitch = 0.0f; break;
    }
    // Fit the face seen along the axis, plus half the depth in front of it.
    const glm::vec3 size(room.size);
    const int a = (axis + 1) % 3, b = (axis + 2) % 3;
    const float half_extent = 0.5f * std::max(size[a], size[b]);
    c.distance = 1.15f * half_extent / std::tan(0.5f * c.fov_y) + 0.5f * size[axis];
    return c;
}

void orbit(OrbitCamera& c, float delta_yaw, float delta_pitch) {
    c.yaw = std::remainder(c.yaw + delta_yaw, 2.0f * 3.14159265f);
    c.pitch = std::clamp(c.pitch + delta_pitch, -max_pitch, max_pitch);
}

void pan(OrbitCamera& c, glm::vec2 pixels, float viewport_height) {
    // World size of one pixel at the target's depth.
    const float metres_per_pixel = 2.0f * c.distance * std::tan(0.5f * c.fov_y) / std::max(viewport_height, 1.0f);
    c.target -= camera_right(c) * (pixels.x * metres_per_pixel);
    c.target += camera_up(c) * (pixels.y * metres_per_pixel);
}

void zoom(OrbitCamera& c, float wheel_steps) {
    c.distance = std::clamp(c.distance * std::pow(0.88f, wheel_steps), 1e-3f, 1e6f);
}

void fly(OrbitCamera& c, glm::vec3 move, float real_dt) {
    // Speed scales with the distance so small and large rooms feel the same.
    const float speed = 0.8f * c.distance;
    c.target += (camera_right(c) * move.x + glm::vec3(0.0f, 1.0f, 0.0f) * move.y + camera_forward(c) * move.z) *
                (speed * real_dt);
}

}  // namespace pl::app
