#include "app/renderer_room.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

namespace pl::app {

namespace {

const glm::vec4 floor_color(0.19f, 0.21f, 0.25f, 0.80f);
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
    for (std::size_t f = 0; f < faces.size(); ++f) {
        const bool is_floor = f == 2;
        auto color_at = [&](glm::vec3 p) {
            if (is_floor) return floor_color;
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
