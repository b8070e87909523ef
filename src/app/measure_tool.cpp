#include "app/measure_tool.hpp"

#include "app/picking.hpp"

#include <imgui.h>

#include <cmath>
#include <cstdio>

namespace pl::app {

namespace {

// Keeps the candidate nearest the cursor.
struct Nearest {
    float mx, my;
    float best_px2 = snap_radius_px * snap_radius_px;
    std::optional<ui::MeasuredPoint> point;

    void offer(const CameraMatrices& cam, const Rect& r, glm::vec3 x, double t, std::size_t variant, std::size_t particle) {
        const std::optional<ScreenPoint> p = project(cam, r, x);
        if (!p || !r.contains(p->x, p->y)) return;
        const float d2 = (p->x - mx) * (p->x - mx) + (p->y - my) * (p->y - my);
        if (d2 >= best_px2) return;
        best_px2 = d2;
        point = ui::MeasuredPoint{Vec3(x), t, variant, particle};
    }
};

}  // namespace

std::optional<ui::MeasuredPoint> snap_measure_point(const ui::LabSession& s, const TrailHistory& trails,
                                                    const std::vector<ViewPane>& panes, const OrbitCamera& camera,
                                                    float mx, float my) {
    if (!s.experiment) return std::nullopt;
    for (const ViewPane& pane : panes) {
        if (!pane.rect.contains(mx, my)) continue;
        const CameraMatrices cam = camera_matrices(camera, pane.rect.w / std::max(pane.rect.h, 1.0f));
        auto shown = [&](std::size_t v) { return !pane.variant || *pane.variant == v; };
        // A ball under the cursor (within ball_snap_px) is picked where it is now, before any
        // trail sample: its newest samples lie a pixel or two away.
        Nearest n{mx, my, ball_snap_px * ball_snap_px, std::nullopt};
        auto offer_balls = [&] {
            for (std::size_t v = 0; v < s.experiment->variant_count(); ++v) {
                if (!shown(v)) continue;
                const ParticleState& st = s.experiment->run(v).state();
                const std::size_t tracked = std::min<std::size_t>(st.size(), 10000);  // beyond: too many to tell apart
                for (std::size_t i = 0; i < tracked; ++i)
                    n.offer(cam, pane.rect, glm::vec3(st.position(i)), s.experiment->time(), v, i);
            }
        };
        offer_balls();
        if (n.point) return n.point;
        n.best_px2 = snap_radius_px * snap_radius_px;
        for (const Trail& trail : trails.trails())
            if (shown(trail.variant))
                for (std::size_t k = 0; k < trail.count; ++k)
                    n.offer(cam, pane.rect, trail.at(k), trail.time_at(k), trail.variant, trail.particle);
        offer_balls();  // failing that, a ball a little farther away
        return n.point;
    }
    return std::nullopt;
}

void measure_click(ui::LabSession& s, const TrailHistory& trails, const std::vector<ViewPane>& panes,
                   const OrbitCamera& camera, float mx, float my) {
    const std::optional<ui::MeasuredPoint> p = snap_measure_point(s, trails, panes, camera, mx, my);
    if (!p) {
        s.status_message = "Measure: no trail sample or ball near the click";
        return;
    }
    if (s.measure_points.size() >= 2) s.measure_points.clear();
    s.measure_points.push_back(*p);
}

void draw_measure_overlay(const ui::LabSession& s, const std::vector<ViewPane>& panes, const OrbitCamera& camera) {
    if (panes.empty() || (!s.measuring && s.measure_points.empty())) return;
    ImDrawList* dl = ImGui::GetBackgroundDrawList();
    const ImU32 colour = IM_COL32(255, 214, 90, 255);
    const ImU32 shadow = IM_COL32(0, 0, 0, 200);
    for (const ViewPane& pane : panes) {
        const CameraMatrices cam = camera_matrices(camera, pane.rect.w / std::max(pane.rect.h, 1.0f));
        std::vector<ImVec2> at;
        for (const ui::MeasuredPoint& p : s.measure_points)
            if (const auto q = project(cam, pane.rect, glm::vec3(p.position))) at.emplace_back(q->x, q->y);
        if (at.size() != s.measure_points.size()) continue;  // behind the camera in this pane
        dl->PushClipRect(ImVec2(pane.rect.x, pane.rect.y), ImVec2(pane.rect.x + pane.rect.w, pane.rect.bottom()), true);
        if (at.size() == 2) dl->AddLine(at[0], at[1], colour, 2.0f);
        for (const ImVec2& q : at) {
            dl->AddCircle(q, 6.0f, shadow, 16, 3.5f);
            dl->AddCircle(q, 6.0f, colour, 16, 2.0f);
        }
        char text[160];
        if (at.size() == 2) {
            const ui::MeasuredPoint &a = s.measure_points[0], &b = s.measure_points[1];
            std::snprintf(text, sizeof text, "%.3f m, %.3f s", glm::length(b.position - a.position), std::abs(b.t - a.t));
        } else {
            std::snprintf(text, sizeof text, at.empty() ? "Measure: click a ball or a trail" : "Measure: click a second point");
        }
        const ImVec2 where = at.size() == 2   ? ImVec2(0.5f * (at[0].x + at[1].x) + 10.0f, 0.5f * (at[0].y + at[1].y))
                             : at.size() == 1 ? ImVec2(at[0].x + 10.0f, at[0].y - 18.0f)
                                              : ImVec2(pane.rect.x + 10.0f, pane.rect.y + 30.0f);
        dl->AddText(ImVec2(where.x + 1.0f, where.y + 1.0f), shadow, text);
        dl->AddText(where, colour, text);
        dl->PopClipRect();
    }
}

}  // namespace pl::app
