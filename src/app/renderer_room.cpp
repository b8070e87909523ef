#include "app/renderer_room.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace pl::app {

namespace {

// The floor is lit as if by a lamp over the room's centre: lighter in the middle, darker towards
// the walls (the colour is interpolated across a grid of quads), so the floor reads as a surface
// under the grid and the balls' shadows and drop lines stand out against it.
const glm::vec4 floor_centre_color(0.30f, 0.33f, 0.39f, 0.92f);
const glm::vec4 floor_edge_color(0.13f, 0.145f, 0.175f, 0.92f);
constexpr int floor_cells = 24;  // quads per side
const glm::vec4 wall_color(0.20f, 0.225f, 0.27f, 0.55f);
const glm::vec4 grid_major_color(0.62f, 0.68f, 0.78f, 0.30f);
const glm::vec4 grid_minor_color(0.62f, 0.68f, 0.78f, 0.10f);
const glm::vec4 edge_color(0.60f, 0.66f, 0.76f, 0.75f);

double nice_step(double raw) {
    const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
    for (double m : {1.0, 2.0, 5.0, 10.0})
        if (m * magnitude >= raw) return m * magnitude;
    return 10.0 * magnitude;
}

void add_lines_along(const Room& room, double step, int axis, glm::vec4 color, LineSegments& out) {
    // Lines at whole multiples of `step` in `axis` (x or z), spanning the floor along the other.
    const Vec3 lo = room.min_corner(), hi = room.max_corner();
    const int other = axis == 0 ? 2 : 0;
    const auto y = static_cast<float>(lo.y);
    for (double c = std::ceil(lo[axis] / step - 1e-9) * step; c <= hi[axis] + 1e-9 * step; c += step) {
        glm::vec3 a(0.0f, y, 0.0f), b(0.0f, y, 0.0f);
        a[axis] = b[axis] = static_cast<float>(c);
        a[other] = static_cast<float>(lo[other]);
        b[other] = static_cast<float>(hi[other]);
        add_segment(out, a, b, color);
    }
}

struct SurfaceVertex {
    glm::vec3 position;
    glm::vec4 color;
};

// Shade at a floor point: 1 - r^2 falloff with r the distance from the centre over the half
// diagonal (0 at the centre, 1 in the corners).
glm::vec4 floor_color_at(glm::vec3 p, glm::vec3 lo, glm::vec3 hi) {
    const glm::vec2 half(0.5f * (hi.x - lo.x), 0.5f * (hi.z - lo.z));
    const glm::vec2 d(p.x - 0.5f * (lo.x + hi.x), p.z - 0.5f * (lo.z + hi.z));
    const float r2 = glm::dot(d, d) / std::max(glm::dot(half, half), 1e-12f);
    return glm::mix(floor_centre_color, floor_edge_color, std::clamp(r2, 0.0f, 1.0f));
}

// The floor as floor_cells^2 quads, facing up (counter-clockwise seen from above).
void add_floor(glm::vec3 lo, glm::vec3 hi, std::vector<SurfaceVertex>& out) {
    auto at = [&](int i, int k) {
        const glm::vec3 p(lo.x + (hi.x - lo.x) * static_cast<float>(i) / floor_cells, lo.y,
                          lo.z + (hi.z - lo.z) * static_cast<float>(k) / floor_cells);
        return SurfaceVertex{p, floor_color_at(p, lo, hi)};
    };
    for (int i = 0; i < floor_cells; ++i)
        for (int k = 0; k < floor_cells; ++k)
            for (const auto& [di, dk] : {std::pair{0, 0}, {0, 1}, {1, 1}, {0, 0}, {1, 1}, {1, 0}}) out.push_back(at(i + di, k + dk));
}

}  // namespace

GridSpacing floor_grid_spacing(const Room& room) {
    const double extent = std::max(room.size.x, room.size.z);
    GridSpacing g;
    g.major = (extent >= 2.0 && extent <= 50.0) ? 1.0 : nice_step(extent / 10.0);
    const double minor = g.major / (extent / g.major <= 6.0 ? 10.0 : 2.0);
    g.minor = extent / minor <= 30.0 ? minor : 0.0;
    return g;
}

RoomRenderer::RoomRenderer() : program_(load_program("surface")), vao_(make_vertex_array()), buffer_(make_buffer()) {
    glBindVertexArray(vao_.get());
    glBindBuffer(GL_ARRAY_BUFFER, buffer_.get());
    const auto stride = static_cast<GLsizei>(sizeof(SurfaceVertex));
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<const void*>(offsetof(SurfaceVertex, position)));
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<const void*>(offsetof(SurfaceVertex, color)));
    glBindVertexArray(0);
}

void RoomRenderer::draw_walls(const Room& room, const CameraMatrices& camera) {
    const glm::vec3 lo(room.min_corner()), hi(room.max_corner());
    auto corner = [&](int i) { return glm::vec3(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z); };
    // Each face listed counter-clockwise as seen from outside; the triangles below reverse it, so
    // front faces look into the room. The walls fade towards the ceiling.
    const std::array<std::array<int, 4>, 6> faces{{
        {0, 4, 6, 2},  // x min
        {1, 3, 7, 5},  // x max
        {0, 1, 5, 4},  // y min (floor)
        {2, 6, 7, 3},  // y max
        {0, 2, 3, 1},  // z min
        {4, 5, 7, 6},  // z max
    }};
    std::vector<SurfaceVertex> vertices;
    add_floor(lo, hi, vertices);
    for (std::size_t f = 0; f < faces.size(); ++f) {
        if (f == 2) continue;  // the floor: add_floor
        auto color_at = [&](glm::vec3 p) {
            const float up = (p.y - lo.y) / std::max(hi.y - lo.y, 1e-6f);
            glm::vec4 c = wall_color;
            c.a *= 1.0f - 0.6f * up;
            return c;
        };
        for (std::size_t k : {0u, 2u, 1u, 0u, 3u, 2u}) {
            const glm::vec3 p = corner(faces[f][k]);
            vertices.push_back({p, color_at(p)});
        }
    }
    upload_stream(GL_ARRAY_BUFFER, buffer_.get(), vertices.data(), vertices.size() * sizeof(SurfaceVertex));
    program_.use();
    program_.set("u_view_proj", camera.view_proj);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    glFrontFace(GL_CCW);
    glDepthMask(GL_FALSE);
    glBindVertexArray(vao_.get());
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(vertices.size()));
    glBindVertexArray(0);
    glDepthMask(GL_TRUE);
    glDisable(GL_CULL_FACE);
}

void RoomRenderer::append_floor_grid(const Room& room, LineSegments& out) {
    const GridSpacing g = floor_grid_spacing(room);
    if (g.minor > 0.0)
        for (int axis : {0, 2}) add_lines_along(room, g.minor, axis, grid_minor_color, out);
    for (int axis : {0, 2}) add_lines_along(room, g.major, axis, grid_major_color, out);
}

void RoomRenderer::append_edges(const Room& room, LineSegments& out) {
    const glm::vec3 lo(room.min_corner()), hi(room.max_corner());
    auto corner = [&](int i) { return glm::vec3(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z); };
    for (int i = 0; i < 8; ++i)
        for (int bit : {1, 2, 4})
            if (!(i & bit)) add_segment(out, corner(i), corner(i | bit), edge_color);
}

}  // namespace pl::app
