#include "app/point_splat.hpp"

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>

namespace pl::app {

namespace {

constexpr float empty_depth = 2.0f;  // beyond the far plane's 1

// The light of shaders/point_sprite.frag: ambient 0.35 plus 0.75 of the diffuse term.
const glm::vec3 light_dir = glm::normalize(glm::vec3(0.35f, 0.65f, 0.65f));

std::uint32_t pack(glm::vec3 rgb, float alpha) {
    auto byte = [](float v) { return static_cast<std::uint32_t>(std::clamp(v, 0.0f, 1.0f) * 255.0f + 0.5f); };
    return byte(rgb.r) | byte(rgb.g) << 8 | byte(rgb.b) << 16 | byte(alpha) << 24;
}

// A point on screen: its centre in window pixels, its diameter and its window depth.
struct ScreenPoint {
    float x, y, size, depth;
};

// Projects like shaders/point_sprite.vert; false when GL would clip the point (its centre
// outside the near and far planes or behind the eye).
bool project(const SphereInstance& s, const glm::mat4& view, const glm::mat4& proj, int width, int height,
             ScreenPoint& out) {
    const glm::vec4 eye = view * glm::vec4(glm::vec3(s.center_radius), 1.0f);
    const glm::vec4 clip = proj * eye;
    if (!(clip.w > 0.0f) || std::abs(clip.z) > clip.w) return false;
    const float inv_w = 1.0f / clip.w;
    out.x = (clip.x * inv_w * 0.5f + 0.5f) * static_cast<float>(width);
    out.y = (clip.y * inv_w * 0.5f + 0.5f) * static_cast<float>(height);
    out.depth = clip.z * inv_w * 0.5f + 0.5f;
    const float diameter = s.center_radius.w * proj[1][1] * static_cast<float>(height) / std::max(-eye.z, 1e-4f);
    out.size = std::clamp(diameter, min_point_diameter_px, max_point_diameter_px);
    return std::isfinite(out.x) && std::isfinite(out.y);
}

void draw_disc(const ScreenPoint& p, const glm::vec4& color, SplatImage& image) {
    const float half = 0.5f * p.size;
    // Pixels whose centres (i + 0.5) lie in [x - half, x + half), as GL rasterises a point.
    const int x0 = std::max(0, static_cast<int>(std::ceil(p.x - half - 0.5f)));
    const int x1 = std::min(image.width, static_cast<int>(std::ceil(p.x + half - 0.5f)));
    const int y0 = std::max(0, static_cast<int>(std::ceil(p.y - half - 0.5f)));
    const int y1 = std::min(image.height, static_cast<int>(std::ceil(p.y + half - 0.5f)));
    const float inv_half = 1.0f / half;
    const glm::vec3 rgb(color);
    for (int y = y0; y < y1; ++y) {
        const float up = (static_cast<float>(y) + 0.5f - p.y) * inv_half;
        const std::size_t row = static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width);
        for (int x = x0; x < x1; ++x) {
            const float right = (static_cast<float>(x) + 0.5f - p.x) * inv_half;
            const float r2 = right * right + up * up;
            if (r2 > 1.0f || p.depth > image.depth[row + x]) continue;
            const glm::vec3 normal(right, up, std::sqrt(1.0f - r2));
            const float diffuse = std::max(glm::dot(normal, light_dir), 0.0f);
            image.depth[row + x] = p.depth;
            image.rgba[row + x] = pack(rgb * (0.35f + 0.75f * diffuse), color.a);
        }
    }
}

}  // namespace

void SplatImage::clear(int w, int h) {
    width = std::max(w, 0);
    height = std::max(h, 0);
    const auto n = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    rgba.assign(n, 0u);
    depth.assign(n, empty_depth);
}

void splat_points(const std::vector<SphereInstance>& instances, const glm::mat4& view, const glm::mat4& proj,
                  int width, int height, SplatImage& image) {
    image.clear(width, height);
    for (const SphereInstance& s : instances) {
        ScreenPoint p{};
        if (project(s, view, proj, width, height, p)) draw_disc(p, s.color, image);
    }
}

}  // namespace pl::app
