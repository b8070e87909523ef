#include "app/picking.hpp"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <cmath>
#include <limits>

namespace pl::app {

Ray ray_through(const CameraMatrices& camera, const Rect& pane, float mouse_x, float mouse_y) {
    const float ndc_x = 2.0f * (mouse_x - pane.x) / pane.w - 1.0f;
    const float ndc_y = 1.0f - 2.0f * (mouse_y - pane.y) / pane.h;
    const glm::mat4 inverse = glm::inverse(camera.view_proj);
    glm::vec4 near_point = inverse * glm::vec4(ndc_x, ndc_y, -1.0f, 1.0f);
    glm::vec4 far_point = inverse * glm::vec4(ndc_x, ndc_y, 1.0f, 1.0f);
    near_point /= near_point.w;
    far_point /= far_point.w;
    return {glm::vec3(near_point), glm::normalize(glm::vec3(far_point - near_point))};
}

std::optional<ParticleRef> pick_particle(const Experiment& e, std::optional<std::size_t> only_variant, const Ray& ray,
                                         const OrbitCamera& camera, float pane_height_px, float min_pick_radius_px) {
    // Metres per pixel at distance 1 along the view.
    const float pixel_at_unit_depth = pixel_size_at_unit_depth(camera, pane_height_px);
    const glm::vec3 forward = camera_forward(camera);
    std::optional<ParticleRef> best;
    float best_t = std::numeric_limits<float>::infinity();
    for (std::size_t v = 0; v < e.variant_count(); ++v) {
        if (only_variant && v != *only_variant) continue;
        const ParticleState& s = e.run(v).state();
        for (std::size_t i = 0; i < s.size(); ++i) {
            const glm::vec3 c(s.position(i));
            const glm::vec3 to_center = c - ray.origin;
            const float along = glm::dot(to_center, ray.direction);
            if (along <= 0.0f) continue;
            const float depth = std::max(glm::dot(to_center, forward), 1e-6f);
            const float r = std::max(static_cast<float>(s.radius[i]), min_pick_radius_px * pixel_at_unit_depth * depth);
            const float miss2 = glm::dot(to_center, to_center) - along * along;
            if (miss2 > r * r) continue;
            const float t = along - std::sqrt(std::max(r * r - miss2, 0.0f));
            if (t < best_t) {
                best_t = t;
                best = ParticleRef{v, i};
            }
        }
    }
    return best;
}

std::optional<ScreenPoint> project(const CameraMatrices& camera, const Rect& pane, glm::vec3 world) {
    const glm::vec4 clip = camera.view_proj * glm::vec4(world, 1.0f);
    if (clip.w <= 1e-6f) return std::nullopt;
    const float ndc_x = clip.x / clip.w, ndc_y = clip.y / clip.w;
    return ScreenPoint{pane.x + (0.5f * ndc_x + 0.5f) * pane.w, pane.y + (0.5f - 0.5f * ndc_y) * pane.h, clip.w};
}

}  // namespace pl::app
