#include "app/view_input.hpp"

#include "app/picking.hpp"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <cmath>

namespace pl::app {

namespace {

constexpr float orbit_rad_per_px = 0.006f;
constexpr float click_tolerance_px = 4.0f;
constexpr float key_orbit_rad_per_s = 1.4f;

std::optional<std::size_t> pane_under(const std::vector<ViewPane>& panes, float x, float y) {
    for (std::size_t k = 0; k < panes.size(); ++k)
        if (panes[k].rect.contains(x, y)) return k;
    return std::nullopt;
}

}  // namespace

std::optional<HoveredParticle> handle_view_mouse(ViewDrag& drag, OrbitCamera& camera, const std::vector<ViewPane>& panes,
                                                 ui::LabSession& session) {
    const ImGuiIO& io = ImGui::GetIO();
    const float mx = io.MousePos.x, my = io.MousePos.y;
    const std::optional<std::size_t> pane =
        io.WantCaptureMouse || !ImGui::IsMousePosValid() ? std::nullopt : pane_under(panes, mx, my);

    if (drag.button < 0 && pane) {
        for (int b : {ImGuiMouseButton_Left, ImGuiMouseButton_Right, ImGuiMouseButton_Middle})
            if (ImGui::IsMouseClicked(b)) {
                drag = ViewDrag{};
                drag.button = b;
                drag.press_x = mx;
                drag.press_y = my;
                drag.aiming = b == ImGuiMouseButton_Left && io.KeyCtrl;
                if (drag.aiming) begin_launch_aim(drag.aim, session, panes, *pane, camera, mx, my);
                break;
            }
    }
    bool clicked = false;
    drag.clicked = false;
    if (drag.button >= 0) {
        if (std::hypot(mx - drag.press_x, my - drag.press_y) > click_tolerance_px) drag.moved = true;
        const ImVec2 d = io.MouseDelta;
        const bool pan_drag = drag.button != ImGuiMouseButton_Left || io.KeyShift;
        if (drag.aiming) {
            if (ImGui::IsMouseClicked(ImGuiMouseButton_Right)) cancel_launch_aim(drag.aim);
            update_launch_aim(drag.aim, session, panes, camera, mx, my);
        } else if (drag.moved && (d.x != 0.0f || d.y != 0.0f)) {
            if (pan_drag) {
                const float height = pane ? panes[*pane].rect.h : panes.front().rect.h;
                pan(camera, glm::vec2(d.x, d.y), height);
            } else {
                orbit(camera, -d.x * orbit_rad_per_px, d.y * orbit_rad_per_px);
            }
        }
        if (!ImGui::IsMouseDown(drag.button)) {
            clicked = !drag.moved && drag.button == ImGuiMouseButton_Left;
            drag.clicked = clicked && !drag.aiming;
            // A Ctrl+click without a drag only selects (below): nothing is launched.
            if (drag.aiming && drag.moved) finish_launch_aim(drag.aim, session);
            cancel_launch_aim(drag.aim);
            drag.button = -1;
        }
    }
    if (pane && io.MouseWheel != 0.0f) zoom(camera, io.MouseWheel);

    if (!pane || !session.experiment || (drag.button >= 0 && (drag.moved || drag.aiming))) return std::nullopt;
    const ViewPane& p = panes[*pane];
    const CameraMatrices cam = camera_matrices(camera, p.rect.w / std::max(p.rect.h, 1.0f));
    const std::optional<ParticleRef> hit =
        pick_particle(*session.experiment, p.variant, ray_through(cam, p.rect, mx, my), camera, p.rect.h);
    if (!hit) return std::nullopt;
    if (clicked && !session.measuring) {
        session.selected_variant = static_cast<int>(hit->variant);
        session.selected_particle = static_cast<int>(hit->particle);
    }
    return HoveredParticle{*hit, *pane};
}

void handle_view_keys(GLFWwindow* window, const InputQueue& input, OrbitCamera& camera, float real_dt) {
    const ImGuiIO& io = ImGui::GetIO();
    if (io.WantCaptureKeyboard || io.WantTextInput) return;
    auto held = [&](int key) {
        return glfwGetKey(window, key) == GLFW_PRESS && !input.chorded.test(static_cast<std::size_t>(key)) ? 1.0f : 0.0f;
    };
    // Ctrl+Q quits, Ctrl+S saves...: letters held with a modifier are shortcuts, not flying.
    for (int modifier : {GLFW_KEY_LEFT_CONTROL, GLFW_KEY_RIGHT_CONTROL, GLFW_KEY_LEFT_ALT, GLFW_KEY_RIGHT_ALT,
                         GLFW_KEY_LEFT_SUPER, GLFW_KEY_RIGHT_SUPER})
        if (glfwGetKey(window, modifier) == GLFW_PRESS) return;
    const glm::vec3 move(held(GLFW_KEY_D) - held(GLFW_KEY_A), held(GLFW_KEY_E) - held(GLFW_KEY_Q),
                         held(GLFW_KEY_W) - held(GLFW_KEY_S));
    if (move != glm::vec3(0.0f)) fly(camera, move, real_dt);
    const float yaw = held(GLFW_KEY_LEFT) - held(GLFW_KEY_RIGHT);
    const float pitch = held(GLFW_KEY_UP) - held(GLFW_KEY_DOWN);
    if (yaw != 0.0f || pitch != 0.0f) orbit(camera, yaw * key_orbit_rad_per_s * real_dt, pitch * key_orbit_rad_per_s * real_dt);
}

}  // namespace pl::app
