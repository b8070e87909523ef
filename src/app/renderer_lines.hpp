// Anti-aliased lines of any pixel width (segments expanded to quads in a geometry shader):
// room edges, floor grid, trails and arrows.
#pragma once

#include "app/renderer_shader.hpp"

#include <glm/vec4.hpp>

#include <vector>

namespace pl::app {

struct LineVertex {
    glm::vec3 position;
    glm::vec4 color;
};

// Pairs of vertices, one pair per segment.
using LineSegments = std::vector<LineVertex>;

inline void add_segment(LineSegments& out, glm::vec3 a, glm::vec3 b, glm::vec4 color_a, glm::vec4 color_b) {
    out.push_back({a, color_a});
    out.push_back({b, color_b});
}
inline void add_segment(LineSegments& out, glm::vec3 a, glm::vec3 b, glm::vec4 color) { add_segment(out, a, b, color, color); }

class LineRenderer {
public:
    LineRenderer();
    void draw(const LineSegments& segments, const glm::mat4& view_proj, glm::vec2 viewport_px, float width_px);

private:
    ShaderProgram program_;
    GlVertexArray vao_;
    GlBuffer buffer_;
};

}  // namespace pl::app
