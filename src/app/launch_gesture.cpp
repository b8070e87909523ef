#include "app/launch_gesture.hpp"

#include "app/picking.hpp"
#include "app/renderer_arrows.hpp"
#include "ui/frame_recorder.hpp"
#include "ui/panel_state.hpp"

#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <imgui.h>

#include <algorithm>
#include <cmath>

namespace pl::app {

namespace {

const glm::vec4 aim_color(1.0f, 0.80f, 0.30f, 1.0f);
const glm::vec4 shadow_color(1.0f, 0.80f, 0.30f, 0.35f);

ImU32 to_u32(const glm::vec4& c) { return ImGui::ColorConvertFloat4ToU32(ImVec4(c.r, c.g, c.b, c.a)); }

const Simulation* aimed_run(const ui::LabSession& s, const LaunchAim& aim) {
    if (!s.experiment || aim.variant >= s.experiment->variant_count()) return nullptr;
    const Simulation& run = s.experiment->run(aim.variant);
    return aim.particle < run.particle_count() ? &run : nullptr;
}

// Projects each segment of `lines` into the pane and draws it; segments behind the camera are skipped.
void draw_segments(ImDrawList* dl, const CameraMatrices& cam, const Rect& pane, const LineSegments& lines, float thickness) {
    for (std::size_t k = 0; k + 1 < lines.size(); k += 2) {
        const auto a = project(cam, pane, lines[k].position);
        const auto b = project(cam, pane, lines[k + 1].position);
        if (a && b) dl->AddLine(ImVec2(a->x, a->y), ImVec2(b->x, b->y), to_u32(lines[k].color), thickness);
    }
}

// Speed, elevation and azimuth in a dark box beside the cursor, kept inside the pane. It goes on
// the far side of the cursor from the particle (`anchor`, on screen), so it does not cover the arrow.
void draw_readout(ImDrawList* dl, const Rect& pane, const LaunchAim& aim, double arrow_time_s, ImVec2 anchor) {
    const ui::LaunchPolar p = ui::launch_polar(aim.velocity);
    const std::string text = fmt::format(
        "{:.3g} m/s{}\nelevation {:.1f}\u00b0\nazimuth {:.1f}\u00b0\narrow: straight path in {:.2g} s\nrelease: launch   Esc / right-click: cancel",
        p.speed_mps, aim.clamped ? " (max)" : "", p.elevation_deg, p.azimuth_deg, arrow_time_s);
    const ImVec2 size = ImGui::CalcTextSize(text.c_str());
    constexpr float pad = 6.0f, gap = 18.0f;
    const float w = size.x + 2 * pad, h = size.y + 2 * pad;
    const float after_x = aim.cursor_x + gap, before_x = aim.cursor_x - gap - w;
    const float after_y = aim.cursor_y + gap, before_y = aim.cursor_y - gap - h;
    float x = aim.cursor_x >= anchor.x ? after_x : before_x;
    float y = aim.cursor_y >= anchor.y ? after_y : before_y;
    if (x + w > pane.right()) x = before_x;
    if (x < pane.x) x = after_x;
    if (y + h > pane.bottom()) y = before_y;
    if (y < pane.y) y = after_y;
    x = std::max(x, pane.x);
    y = std::max(y, pane.y);
    dl->AddRectFilled(ImVec2(x, y), ImVec2(x + w, y + h), IM_COL32(18, 20, 26, 215), 4.0f);
    dl->AddRect(ImVec2(x, y), ImVec2(x + w, y + h), to_u32(shadow_color), 4.0f);
    dl->AddText(ImVec2(x + pad, y + pad), IM_COL32(240, 232, 210, 255), text.c_str());
}

}  // namespace

double aim_arrow_time_s(const Room& room) {
    constexpr double reference_speed_mps = 10.0;
    const double raw = std::max({room.size.x, room.size.y, room.size.z}) / reference_speed_mps;
    const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
    double best = magnitude;
    for (double m : {1.0, 2.0, 5.0})
        if (m * magnitude <= raw * (1.0 + 1e-12)) best = m * magnitude;
    return best;
}

std::optional<Vec3> aim_velocity(const OrbitCamera& camera, const Rect& pane, float mouse_x, float mouse_y,
                                 const Vec3& anchor, double arrow_time_s, bool& clamped) {
    const CameraMatrices cam = camera_matrices(camera, pane.w / std::max(pane.h, 1.0f));
    const Ray ray = ray_through(cam, pane, mouse_x, mouse_y);
    const glm::dvec3 normal(camera_forward(camera));
    const glm::dvec3 origin(ray.origin), direction(ray.direction);
    const double facing = glm::dot(direction, normal);
    if (std::abs(facing) < 1e-6) return std::nullopt;
    const double along = glm::dot(anchor - origin, normal) / facing;
    if (!(along > 0.0)) return std::nullopt;
    Vec3 velocity = (origin + along * direction - anchor) / arrow_time_s;
    const double speed = glm::length(velocity);
    clamped = speed > ui::max_launch_speed_mps;
    if (clamped) velocity *= ui::max_launch_speed_mps / speed;
    return velocity;
}

bool begin_launch_aim(LaunchAim& aim, ui::LabSession& s, const std::vector<ViewPane>& panes, std::size_t pane,
                      const OrbitCamera& camera, float mouse_x, float mouse_y) {
    aim = {};
    if (!s.experiment || pane >= panes.size()) return false;
    const ViewPane& p = panes[pane];
    const CameraMatrices cam = camera_matrices(camera, p.rect.w / std::max(p.rect.h, 1.0f));
    if (const auto hit = pick_particle(*s.experiment, p.variant, ray_through(cam, p.rect, mouse_x, mouse_y), camera, p.rect.h)) {
        aim.variant = hit->variant;
        aim.particle = hit->particle;
    } else {
        aim.variant = p.variant.value_or(static_cast<std::size_t>(std::max(s.selected_variant, 0)));
        aim.particle = static_cast<std::size_t>(std::max(s.selected_particle, 0));
        if (aim.variant >= s.experiment->variant_count()) aim.variant = 0;
        if (aimed_run(s, aim) == nullptr) aim.particle = 0;
    }
    const Simulation* run = aimed_run(s, aim);
    if (!run || !project(cam, p.rect, glm::vec3(run->state().position(aim.particle)))) return false;
    s.selected_variant = static_cast<int>(aim.variant);
    s.selected_particle = static_cast<int>(aim.particle);
    aim.pane = pane;
    aim.active = true;
    update_launch_aim(aim, s, panes, camera, mouse_x, mouse_y);
    return aim.active;
}

void update_launch_aim(LaunchAim& aim, const ui::LabSession& s, const std::vector<ViewPane>& panes, const OrbitCamera& camera,
                       float mouse_x, float mouse_y) {
    if (!aim.active) return;
    const Simulation* run = aimed_run(s, aim);
    if (!run || aim.pane >= panes.size()) {
        cancel_launch_aim(aim);
        return;
    }
    aim.cursor_x = mouse_x;
    aim.cursor_y = mouse_y;
    bool clamped = false;
    const double arrow_time_s = aim_arrow_time_s(run->model().room);
    // A cursor off the plane (never for a plane facing the camera, but at grazing angles in
    // principle) keeps the last velocity.
    if (auto v = aim_velocity(camera, panes[aim.pane].rect, mouse_x, mouse_y, run->state().position(aim.particle), arrow_time_s,
                              clamped)) {
        aim.velocity = *v;
        aim.clamped = clamped;
    }
}

void finish_launch_aim(LaunchAim& aim, ui::LabSession& s) {
    if (!aim.active) return;
    aim.active = false;
    if (!aimed_run(s, aim)) return;
    ui::kick_particle(s, aim.particle, aim.velocity);
    s.launch_velocity = aim.velocity;
    ui::panels_of(s).launch_from_velocity = true;  // the Launch section shows the aimed speed and angles
    const ui::LaunchPolar p = ui::launch_polar(aim.velocity);
    s.status_message = fmt::format("Launched particle {} at {:.3g} m/s, elevation {:.1f}\u00b0, azimuth {:.1f}\u00b0", aim.particle,
                                   p.speed_mps, p.elevation_deg, p.azimuth_deg);
}

void draw_launch_aim(const LaunchAim& aim, const ui::LabSession& s, const std::vector<ViewPane>& panes,
                     const OrbitCamera& camera) {
    const Simulation* run = aimed_run(s, aim);
    if (!aim.active || !run || aim.pane >= panes.size()) return;
    const Rect& r = panes[aim.pane].rect;
    const CameraMatrices cam = camera_matrices(camera, r.w / std::max(r.h, 1.0f));
    const double arrow_time_s = aim_arrow_time_s(run->model().room);
    const glm::vec3 from(run->state().position(aim.particle));
    const glm::vec3 to(run->state().position(aim.particle) + aim.velocity * arrow_time_s);
    const float floor_y = static_cast<float>(run->model().room.min_corner().y);
    const glm::vec3 from_floor(from.x, floor_y, from.z), to_floor(to.x, floor_y, to.z);
    const glm::vec3 view_dir = camera_forward(camera);

    // The shadow on the floor and the two plumb lines make the arrow's direction readable in 3D.
    LineSegments shadow, arrow;
    append_arrow(shadow, from_floor, to_floor, shadow_color, glm::vec3(0.0f, -1.0f, 0.0f));
    add_segment(shadow, from, from_floor, shadow_color);
    add_segment(shadow, to, to_floor, shadow_color);
    append_arrow(arrow, from, to, aim_color, view_dir);

    ImDrawList* dl = ImGui::GetBackgroundDrawList();
    dl->PushClipRect(ImVec2(r.x, r.y), ImVec2(r.right(), r.bottom()), true);
    draw_segments(dl, cam, r, shadow, 1.5f);
    draw_segments(dl, cam, r, arrow, 3.0f);
    ImVec2 anchor(aim.cursor_x, aim.cursor_y);
    if (const auto p = project(cam, r, from)) {
        anchor = ImVec2(p->x, p->y);
        dl->AddCircleFilled(anchor, 3.5f, to_u32(aim_color));
    }
    draw_readout(dl, r, aim, arrow_time_s, anchor);
    dl->PopClipRect();
}

}  // namespace pl::app
