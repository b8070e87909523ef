#include "app/view_overlay.hpp"

#include "app/renderer_arrows.hpp"
#include "app/renderer_room.hpp"
#include "ui/palette.hpp"

#include <glm/geometric.hpp>
#include <imgui.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>

namespace pl::app {

namespace {

constexpr ImU32 label_color = IM_COL32(185, 195, 212, 210);
constexpr ImU32 label_shadow = IM_COL32(0, 0, 0, 150);
const std::array<ui::Rgb, 3> axis_colors{{{0.91f, 0.38f, 0.39f}, {0.42f, 0.75f, 0.38f}, {0.31f, 0.61f, 0.91f}}};

ImVec2 to_imvec(const ScreenPoint& p) { return {p.x, p.y}; }
ImU32 to_u32(ui::Rgb c, float alpha = 1.0f) { return ImGui::ColorConvertFloat4ToU32(ImVec4(c.r, c.g, c.b, alpha)); }

void shadowed_text(ImDrawList* dl, ImVec2 at, ImU32 color, const char* text) {
    dl->AddText(ImVec2(at.x + 1, at.y + 1), label_shadow, text);
    dl->AddText(at, color, text);
}

void centered_text(ImDrawList* dl, ImVec2 at, ImU32 color, const char* text) {
    const ImVec2 size = ImGui::CalcTextSize(text);
    shadowed_text(dl, ImVec2(at.x - 0.5f * size.x, at.y - 0.5f * size.y), color, text);
}

std::string format_metres(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", std::abs(v) < 1e-9 ? 0.0 : v);
    return buf;
}

// Labels the grid lines along one edge of the room, thinned out when they would crowd on
// screen, with the axis name beyond one end of the row. `axis` is the world axis the labels run
// along, `origin` is subtracted from the printed values (heights count from the floor).
struct TickRow {
    int axis;
    glm::vec3 base;     // a point on the edge (its `axis` coordinate is ignored)
    glm::vec3 outward;  // offset from the edge to the labels
    double lo, hi, step, origin;
    const char* name;
    bool name_at_low_end;  // the floor rows meet at the corner nearest the camera: name the far end
};

void label_ticks(ImDrawList* dl, const CameraMatrices& cam, const Rect& pane, const TickRow& row) {
    std::vector<std::pair<double, ScreenPoint>> ticks;
    for (double c = std::ceil((row.lo - row.origin) / row.step - 1e-9) * row.step + row.origin; c <= row.hi + 1e-9 * row.step;
         c += row.step) {
        glm::vec3 p = row.base + row.outward;
        p[row.axis] = static_cast<float>(c);
        if (auto s = project(cam, pane, p)) ticks.emplace_back(c - row.origin, *s);
    }
    if (ticks.size() < 2) return;
    const float spacing = std::hypot(ticks[1].second.x - ticks[0].second.x, ticks[1].second.y - ticks[0].second.y);
    long long every = 1;
    for (long long k : {1, 2, 5, 10, 20, 50}) {
        every = k;
        if (spacing * static_cast<float>(k) >= 34.0f) break;
    }
    for (const auto& [value, at] : ticks) {
        if (std::llround(value / row.step) % every != 0) continue;
        centered_text(dl, to_imvec(at), label_color, format_metres(value).c_str());
    }
    // The name continues the row on screen, past its end label.
    const ScreenPoint& end = row.name_at_low_end ? ticks.front().second : ticks.back().second;
    const ScreenPoint& inner = row.name_at_low_end ? ticks[1].second : ticks[ticks.size() - 2].second;
    ImVec2 dir(end.x - inner.x, end.y - inner.y);
    const float len = std::hypot(dir.x, dir.y);
    dir = len > 1e-3f ? ImVec2(dir.x / len, dir.y / len) : ImVec2(0.0f, -1.0f);
    const ImVec2 name_size = ImGui::CalcTextSize(row.name);
    // Distance from the end label's centre to the name's centre along `dir`, clear of both boxes.
    const float reach = 0.5f * (std::abs(dir.x) * (name_size.x + 28.0f) + std::abs(dir.y) * (name_size.y + 14.0f)) + 8.0f;
    // Kept inside the pane, where a narrow split pane would otherwise cut it off.
    const float half_w = 0.5f * name_size.x + 4.0f, half_h = 0.5f * name_size.y + 2.0f;
    auto inside_pane = [&](ImVec2 p) {
        return ImVec2(std::clamp(p.x, pane.x + half_w, std::max(pane.right() - half_w, pane.x + half_w)),
                      std::clamp(p.y, pane.y + half_h, std::max(pane.bottom() - half_h, pane.y + half_h)));
    };
    ImVec2 at = inside_pane(ImVec2(end.x + dir.x * reach, end.y + dir.y * reach));
    // Pushed back by the pane's edge onto the end label (a narrow split pane): above it instead
    // (below it is the axis gizmo's corner), or below it where there is no room above.
    const ImVec2 end_size = ImGui::CalcTextSize(format_metres(row.name_at_low_end ? ticks.front().first : ticks.back().first).c_str());
    const bool overlaps = std::abs(at.x - end.x) < 0.5f * (name_size.x + end_size.x) + 2.0f &&
                          std::abs(at.y - end.y) < 0.5f * (name_size.y + end_size.y) + 1.0f;
    if (overlaps) {
        const float drop = 0.5f * (name_size.y + end_size.y) + 3.0f;
        const float above = end.y - drop;
        at = inside_pane(ImVec2(end.x, above - half_h >= pane.y ? above : end.y + drop));
    }
    centered_text(dl, at, to_u32(axis_colors[static_cast<std::size_t>(row.axis)], 0.95f), row.name);
}

void draw_metre_marks(ImDrawList* dl, const CameraMatrices& cam, const Rect& pane, const Room& room) {
    const double step = floor_grid_spacing(room).major;
    const glm::vec3 lo(room.min_corner()), hi(room.max_corner()), centre(room.center);
    const glm::vec3 eye = cam.eye;
    // Label the floor edges nearest the camera, just outside the room.
    const float near_z = eye.z >= centre.z ? hi.z : lo.z;
    const float near_x = eye.x >= centre.x ? hi.x : lo.x;
    const float far_z = eye.z >= centre.z ? lo.z : hi.z;
    const float far_x = eye.x >= centre.x ? lo.x : hi.x;
    const float margin = 0.045f * std::max({hi.x - lo.x, hi.z - lo.z});
    const float out_z = eye.z >= centre.z ? margin : -margin;
    const float out_x = eye.x >= centre.x ? margin : -margin;
    label_ticks(dl, cam, pane,
                {0, {0.0f, lo.y, near_z}, {0.0f, 0.0f, out_z}, lo.x, hi.x, step, 0.0, "x (m)", far_x < centre.x});
    label_ticks(dl, cam, pane,
                {2, {near_x, lo.y, 0.0f}, {out_x, 0.0f, 0.0f}, lo.z, hi.z, step, 0.0, "z (m)", far_z < centre.z});
    // Height above the floor on the farthest vertical edge, clear of both floor rows; its 0 would
    // sit on the floor corner, so it starts one step up.
    const glm::vec3 corner_out = glm::normalize(glm::vec3(far_x - centre.x, 0.0f, far_z - centre.z)) * margin;
    label_ticks(dl, cam, pane, {1, {far_x, 0.0f, far_z}, corner_out, lo.y + step, hi.y, step, lo.y, "height (m)", false});
}

void draw_axis_gizmo(ImDrawList* dl, const CameraMatrices& cam, const Rect& pane) {
    const ImVec2 origin(pane.x + 34.0f, pane.bottom() - 34.0f);
    constexpr float length = 24.0f;
    struct Axis {
        int index;
        glm::vec3 dir;  // view space
    };
    std::array<Axis, 3> axes{};
    for (int a = 0; a < 3; ++a) {
        glm::vec4 w(0.0f);
        w[a] = 1.0f;
        axes[static_cast<std::size_t>(a)] = {a, glm::vec3(cam.view * w)};
    }
    // Far axes first so the near ones are drawn on top.
    std::sort(axes.begin(), axes.end(), [](const Axis& a, const Axis& b) { return a.dir.z < b.dir.z; });
    const char* names[3] = {"x", "y", "z"};
    for (const Axis& a : axes) {
        const ImVec2 tip(origin.x + a.dir.x * length, origin.y - a.dir.y * length);
        const ImU32 col = to_u32(axis_colors[static_cast<std::size_t>(a.index)], 0.95f);
        dl->AddLine(origin, tip, col, 2.0f);
        const ImVec2 label(origin.x + a.dir.x * (length + 9.0f), origin.y - a.dir.y * (length + 9.0f));
        centered_text(dl, label, col, names[a.index]);
    }
}

float projected_radius_px(const CameraMatrices& cam, const Rect& pane, float radius, float depth) {
    return radius * cam.proj[1][1] * 0.5f * pane.h / std::max(depth, 1e-6f);
}

void ring_particle(ImDrawList* dl, const CameraMatrices& cam, const Rect& pane, const Simulation& run, std::size_t i,
                   ImU32 color, float thickness) {
    if (i >= run.particle_count()) return;
    const ParticleState& s = run.state();
    if (auto p = project(cam, pane, glm::vec3(s.position(i)))) {
        const float r = projected_radius_px(cam, pane, static_cast<float>(s.radius[i]), p->depth);
        dl->AddCircle(to_imvec(*p), std::max(r, 3.0f) + 4.0f, color, 40, thickness);
    }
}

void draw_legend(ImDrawList* dl, const Rect& pane, const Experiment& e, std::optional<std::size_t> only_variant) {
    ImVec2 at(pane.x + 10.0f, pane.y + 8.0f);
    const float line = ImGui::GetTextLineHeightWithSpacing();
    const std::size_t variants = e.variant_count();
    for (std::size_t v = 0; v < variants; ++v) {
        if (only_variant && v != *only_variant) continue;
        const std::string& label = e.run(v).model().label;
        const std::string text = label.empty() ? "variant " + std::to_string(v + 1) : label;
        const ui::Rgb c = ui::series_color(variants, v, 0);
        dl->AddCircleFilled(ImVec2(at.x + 5.0f, at.y + 0.5f * line), 5.0f, to_u32(c));
        shadowed_text(dl, ImVec2(at.x + 16.0f, at.y + 1.0f), IM_COL32(225, 230, 238, 240), text.c_str());
        at.y += line;
    }
}

// Names whose wind the arrows show (overlaid variants can differ), or says there is none.
void draw_wind_caption(ImDrawList* dl, const Rect& pane, const Experiment& e, std::optional<std::size_t> pane_variant,
                       std::size_t selected_variant) {
    const std::optional<std::size_t> v = wind_variant_to_show(e, pane_variant, selected_variant);
    std::string text;
    if (!v) text = "no wind here";
    else {
        const std::string kind = to_string(e.run(*v).wind().kind());
        const std::string& label = e.run(*v).model().label;
        text = "wind: " + (pane_variant || label.empty() || label == kind ? kind : label + " (" + kind + ")");
    }
    const ImVec2 size = ImGui::CalcTextSize(text.c_str());
    shadowed_text(dl, ImVec2(pane.right() - size.x - 12.0f, pane.bottom() - size.y - 10.0f), IM_COL32(140, 215, 240, 230),
                  text.c_str());
}

void draw_time_badge(ImDrawList* dl, const Rect& pane, const ui::LabSession& s) {
    char text[64];
    std::snprintf(text, sizeof text, "t = %.3f s", s.experiment->time());
    const ImVec2 size = ImGui::CalcTextSize(text);
    ImVec2 at(pane.right() - size.x - 12.0f, pane.y + 8.0f);
    shadowed_text(dl, at, IM_COL32(225, 230, 238, 240), text);
    if (s.paused) {
        const char* paused = "PAUSED";
        const ImVec2 ps = ImGui::CalcTextSize(paused);
        const ImVec2 p(pane.right() - ps.x - 12.0f, at.y + size.y + 4.0f);
        dl->AddRectFilled(ImVec2(p.x - 5, p.y - 1), ImVec2(p.x + ps.x + 5, p.y + ps.y + 1), IM_COL32(245, 190, 70, 60), 3.0f);
        dl->AddText(p, IM_COL32(250, 205, 100, 255), paused);
    }
}

}  // namespace

void draw_view_overlay(const ui::LabSession& session, const std::vector<ViewPane>& panes, const OrbitCamera& camera,
                       const std::optional<HoveredParticle>& hovered) {
    if (!session.experiment || panes.empty()) return;
    const Experiment& e = *session.experiment;
    ImDrawList* dl = ImGui::GetBackgroundDrawList();
    const std::size_t selected_particle = static_cast<std::size_t>(std::max(session.selected_particle, 0));
    const std::size_t selected_variant = static_cast<std::size_t>(std::max(session.selected_variant, 0));
    std::size_t top_right = 0;  // the time badge goes to the view's top-right corner
    for (std::size_t k = 1; k < panes.size(); ++k)
        if (panes[k].rect.y < panes[top_right].rect.y ||
            (panes[k].rect.y == panes[top_right].rect.y && panes[k].rect.x > panes[top_right].rect.x))
            top_right = k;
    for (std::size_t k = 0; k < panes.size(); ++k) {
        const ViewPane& pane = panes[k];
        const Rect& r = pane.rect;
        dl->PushClipRect(ImVec2(r.x, r.y), ImVec2(r.right(), r.bottom()), true);
        const CameraMatrices cam = camera_matrices(camera, r.w / std::max(r.h, 1.0f));
        draw_metre_marks(dl, cam, r, e.scene().room);
        draw_axis_gizmo(dl, cam, r);
        if (e.variant_count() > 1) draw_legend(dl, r, e, pane.variant);
        if (k == top_right) draw_time_badge(dl, r, session);
        if (k == top_right && pane.variant && panes.size() < e.variant_count()) {
            // Say that some variants have no pane, under the time badge.
            char text[96];
            std::snprintf(text, sizeof text, "%zu of %zu variants shown", panes.size(), e.variant_count());
            const ImVec2 size = ImGui::CalcTextSize(text);
            shadowed_text(dl, ImVec2(r.right() - size.x - 12.0f, r.y + 2.6f * size.y + 8.0f), IM_COL32(250, 205, 100, 255), text);
        }
        if (session.show_wind) draw_wind_caption(dl, r, e, pane.variant, selected_variant);
        // Selection: in a split pane the selected particle of that pane's variant.
        const std::size_t ring_variant = pane.variant.value_or(selected_variant);
        if (ring_variant < e.variant_count())
            ring_particle(dl, cam, r, e.run(ring_variant), selected_particle, IM_COL32(255, 255, 255, 230), 2.0f);
        if (hovered && hovered->pane == k)
            ring_particle(dl, cam, r, e.run(hovered->particle.variant), hovered->particle.particle,
                          IM_COL32(255, 255, 255, 120), 1.5f);
        dl->PopClipRect();
    }
}

}  // namespace pl::app
