#include "app/scene_renderer.hpp"

#include "app/renderer_arrows.hpp"
#include "app/renderer_contacts.hpp"
#include "app/renderer_trails.hpp"
#include "ui/palette.hpp"

#include <algorithm>
#include <cmath>

namespace pl::app {

namespace {

// The particles of the variants a pane shows, in their series colours; with `tint_sleeping`,
// those asleep in the slate tint (a run without collisions has no sleep flags: nothing to tint).
void build_instances(const Experiment& e, std::optional<std::size_t> only_variant, bool tint_sleeping,
                     std::vector<SphereInstance>& out) {
    out.clear();
    const std::size_t variants = e.variant_count();
    for (std::size_t v = 0; v < variants; ++v) {
        if (only_variant && v != *only_variant) continue;
        const ParticleState& s = e.run(v).state();
        const std::vector<std::uint8_t>* asleep = tint_sleeping ? &e.run(v).asleep() : nullptr;
        if (asleep && asleep->size() != s.size()) asleep = nullptr;
        for (std::size_t i = 0; i < s.size(); ++i) {
            const ui::Rgb c = ui::series_color(variants, v, i);
            glm::vec3 color(c.r, c.g, c.b);
            if (asleep && (*asleep)[i]) color = sleeping_tint(color);
            out.push_back({glm::vec4(static_cast<float>(s.x[i]), static_cast<float>(s.y[i]), static_cast<float>(s.z[i]),
                                     static_cast<float>(s.radius[i])),
                           glm::vec4(color, 1.0f)});
        }
    }
}

}  // namespace

SceneRenderer::SceneRenderer()
    : spheres_(instances_), points_(instances_), shadows_(instances_),
      splat_on_cpu_(splat_points_on_cpu(reinterpret_cast<const char*>(glGetString(GL_RENDERER)))) {}

LineSegments& SceneRenderer::PanePlan::add_overlay(float width_px, bool through_balls) {
    if (overlay_count == overlays.size()) overlays.emplace_back();
    LineBatch& batch = overlays[overlay_count++];
    batch.segments.clear();
    batch.width_px = width_px;
    batch.through_balls = through_balls;
    return batch.segments;
}

void SceneRenderer::prepare(const ui::LabSession& session, const TrailHistory& trails, const std::vector<ViewPane>& panes,
                            const OrbitCamera& camera, const FramebufferMapping& fb) {
    plan_count_ = 0;
    if (!session.experiment) return;
    if (plans_.size() < panes.size()) plans_.resize(panes.size());
    for (const ViewPane& pane : panes)
        if (prepare_pane(session, trails, pane, camera, fb, plans_[plan_count_])) ++plan_count_;
}

void SceneRenderer::submit() {
    if (plan_count_ == 0) return;
    glEnable(GL_SCISSOR_TEST);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    for (std::size_t i = 0; i < plan_count_; ++i) submit_pane(plans_[i]);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_DEPTH_TEST);
}

// False when the pane has no pixels (nothing to draw).
bool SceneRenderer::prepare_pane(const ui::LabSession& session, const TrailHistory& trails, const ViewPane& pane,
                                 const OrbitCamera& camera, const FramebufferMapping& fb, PanePlan& plan) {
    const Experiment& e = *session.experiment;
    // ImGui's origin is top-left, GL's bottom-left.
    plan.x = static_cast<GLint>(std::lround(pane.rect.x * fb.scale_x));
    plan.w = static_cast<GLsizei>(std::lround(pane.rect.w * fb.scale_x));
    plan.h = static_cast<GLsizei>(std::lround(pane.rect.h * fb.scale_y));
    plan.y = static_cast<GLint>(fb.height - std::lround(pane.rect.bottom() * fb.scale_y));
    if (plan.w <= 0 || plan.h <= 0) return false;
    plan.cam = camera_matrices(camera, static_cast<float>(plan.w) / static_cast<float>(plan.h));
    plan.min_radius_per_depth = min_sphere_radius_px * pixel_size_at_unit_depth(camera, static_cast<float>(plan.h));
    plan.room = e.scene().room;
    plan.floor_grid.segments.clear();
    RoomRenderer::append_floor_grid(plan.room, plan.floor_grid.segments);
    build_instances(e, pane.variant, session.tint_sleeping, plan.instances);

    plan.overlay_count = 0;
    const glm::vec3 view_dir = camera_forward(camera);
    const auto selected = static_cast<std::size_t>(std::max(session.selected_particle, 0));
    const auto trail_particles = static_cast<std::size_t>(std::max(session.trail_particles, 0));
    if (session.show_trails) append_trails(trails, e, pane.variant, selected, trail_particles, plan.add_overlay(2.0f));
    append_drop_lines(e, pane.variant, selected, trail_particles, plan.add_overlay(1.0f));
    if (const ui::PinBoard* pins = ui::pins_if_any(session); pins && !pins->runs.empty())
        append_pinned_paths(*pins, plan.add_overlay(1.5f));
    if (session.show_velocity) append_velocity_arrows(e, pane.variant, view_dir, plan.add_overlay(1.6f));
    if (session.show_wind) {
        const auto variant_selected = static_cast<std::size_t>(std::max(session.selected_variant, 0));
        LineSegments& arrows = plan.add_overlay(1.4f);
        if (const auto variant = wind_variant_to_show(e, pane.variant, variant_selected))
            append_wind_arrows(e, *variant, view_dir, arrows);
    }
    if (session.show_contacts) append_contacts(e, pane.variant, plan.add_overlay(1.5f, true));
    RoomRenderer::append_edges(plan.room, plan.add_overlay(1.5f));
    return true;
}

void SceneRenderer::draw_lines(const LineBatch& batch, const PanePlan& plan) {
    if (batch.through_balls) glDisable(GL_DEPTH_TEST);
    lines_.draw(batch.segments, plan.cam.view_proj, plan.viewport(), batch.width_px);
    if (batch.through_balls) glEnable(GL_DEPTH_TEST);
}

void SceneRenderer::submit_pane(const PanePlan& plan) {
    glViewport(plan.x, plan.y, plan.w, plan.h);
    glScissor(plan.x, plan.y, plan.w, plan.h);
    glClear(GL_DEPTH_BUFFER_BIT);
    background_.draw();
    room_.draw_walls(plan.room, plan.cam);

    glDepthMask(GL_FALSE);
    draw_lines(plan.floor_grid, plan);
    const bool splat = plan.many() && splat_on_cpu_;
    if (!splat) instances_.upload(plan.instances);
    if (!plan.many())
        shadows_.draw(plan.cam, static_cast<float>(plan.room.floor_y()) + 1e-4f * static_cast<float>(plan.room.size.y),
                      plan.min_radius_per_depth);
    glDepthMask(GL_TRUE);
    if (splat) splat_.draw(plan.instances, plan.cam, plan.x, plan.y, plan.w, plan.h);
    else if (plan.many()) points_.draw(plan.cam, plan.viewport().y);
    else spheres_.draw(plan.cam, plan.min_radius_per_depth);

    glDepthMask(GL_FALSE);
    for (std::size_t i = 0; i < plan.overlay_count; ++i) draw_lines(plan.overlays[i], plan);
    glDepthMask(GL_TRUE);
}

}  // namespace pl::app
