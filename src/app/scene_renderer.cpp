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

SceneRenderer::SceneRenderer() : spheres_(instances_), points_(instances_), shadows_(instances_) {}

void SceneRenderer::draw(const ui::LabSession& session, const TrailHistory& trails, const std::vector<ViewPane>& panes,
                         const OrbitCamera& camera, const FramebufferMapping& fb) {
    if (!session.experiment) return;
    glEnable(GL_SCISSOR_TEST);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    for (const ViewPane& pane : panes) draw_pane(session, trails, pane, camera, fb);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_DEPTH_TEST);
}

void SceneRenderer::draw_pane(const ui::LabSession& session, const TrailHistory& trails, const ViewPane& pane,
                              const OrbitCamera& camera, const FramebufferMapping& fb) {
    const Experiment& e = *session.experiment;
    const Room& room = e.scene().room;
    // ImGui's origin is top-left, GL's bottom-left.
    const auto x = static_cast<GLint>(std::lround(pane.rect.x * fb.scale_x));
    const auto w = static_cast<GLsizei>(std::lround(pane.rect.w * fb.scale_x));
    const auto h = static_cast<GLsizei>(std::lround(pane.rect.h * fb.scale_y));
    const auto y = static_cast<GLint>(fb.height - std::lround(pane.rect.bottom() * fb.scale_y));
    if (w <= 0 || h <= 0) return;
    glViewport(x, y, w, h);
    glScissor(x, y, w, h);
    glClear(GL_DEPTH_BUFFER_BIT);
    const glm::vec2 viewport(static_cast<float>(w), static_cast<float>(h));
    const CameraMatrices cam = camera_matrices(camera, viewport.x / viewport.y);
    const glm::vec3 view_dir = camera_forward(camera);
    const float min_radius_per_depth = min_sphere_radius_px * pixel_size_at_unit_depth(camera, viewport.y);

    background_.draw();
    room_.draw_walls(room, cam);

    glDepthMask(GL_FALSE);
    segments_.clear();
    RoomRenderer::append_floor_grid(room, segments_);
    lines_.draw(segments_, cam.view_proj, viewport, 1.0f);

    build_instances(e, pane.variant, session.tint_sleeping, instance_scratch_);
    instances_.upload(instance_scratch_);
    const bool many = instance_scratch_.size() > max_mesh_spheres;
    if (!many)
        shadows_.draw(cam, static_cast<float>(room.floor_y()) + 1e-4f * static_cast<float>(room.size.y), min_radius_per_depth);
    glDepthMask(GL_TRUE);
    if (many) points_.draw(cam, viewport.y);
    else spheres_.draw(cam, min_radius_per_depth);

    glDepthMask(GL_FALSE);
    const auto selected = static_cast<std::size_t>(std::max(session.selected_particle, 0));
    const auto trail_particles = static_cast<std::size_t>(std::max(session.trail_particles, 0));
    if (session.show_trails) {
        segments_.clear();
        append_trails(trails, e, pane.variant, selected, trail_particles, segments_);
        lines_.draw(segments_, cam.view_proj, viewport, 2.0f);
    }
    segments_.clear();
    append_drop_lines(e, pane.variant, selected, trail_particles, segments_);
    lines_.draw(segments_, cam.view_proj, viewport, 1.0f);
    if (const ui::PinBoard* pins = ui::pins_if_any(session); pins && !pins->runs.empty()) {
        segments_.clear();
        append_pinned_paths(*pins, segments_);
        lines_.draw(segments_, cam.view_proj, viewport, 1.5f);
    }
    if (session.show_velocity) {
        segments_.clear();
        append_velocity_arrows(e, pane.variant, view_dir, segments_);
        lines_.draw(segments_, cam.view_proj, viewport, 1.6f);
    }
    if (session.show_wind) {
        segments_.clear();
        const auto selected = static_cast<std::size_t>(std::max(session.selected_variant, 0));
        if (const auto variant = wind_variant_to_show(e, pane.variant, selected))
            append_wind_arrows(e, *variant, view_dir, segments_);
        lines_.draw(segments_, cam.view_proj, viewport, 1.4f);
    }
    if (session.show_contacts) draw_contacts(e, pane, cam, viewport);
    segments_.clear();
    RoomRenderer::append_edges(room, segments_);
    lines_.draw(segments_, cam.view_proj, viewport, 1.5f);
    glDepthMask(GL_TRUE);
}

// Through the balls (a contact's line lies inside its two spheres, so the depth test would hide
// it): one batched draw of the pane's loaded contacts.
void SceneRenderer::draw_contacts(const Experiment& e, const ViewPane& pane, const CameraMatrices& cam, glm::vec2 viewport) {
    segments_.clear();
    if (append_contacts(e, pane.variant, segments_) == 0) return;
    glDisable(GL_DEPTH_TEST);
    lines_.draw(segments_, cam.view_proj, viewport, 1.5f);
    glEnable(GL_DEPTH_TEST);
}

}  // namespace pl::app
