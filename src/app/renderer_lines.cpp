#include "app/renderer_lines.hpp"

#include <cstddef>

namespace pl::app {

LineRenderer::LineRenderer() : program_(load_program("line", true)), vao_(make_vertex_array()), buffer_(make_buffer()) {
    glBindVertexArray(vao_.get());
    glBindBuffer(GL_ARRAY_BUFFER, buffer_.get());
    const auto stride = static_cast<GLsizei>(sizeof(LineVertex));
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<const void*>(offsetof(LineVertex, position)));
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<const void*>(offsetof(LineVertex, color)));
    glBindVertexArray(0);
}

void LineRenderer::draw(const LineSegments& segments, const glm::mat4& view_proj, glm::vec2 viewport_px, float width_px) {
    if (segments.size() < 2) return;
    upload_stream(GL_ARRAY_BUFFER, buffer_.get(), segments.data(), segments.size() * sizeof(LineVertex));
    program_.use();
    program_.set("u_view_proj", view_proj);
    program_.set("u_viewport_size", viewport_px);
    program_.set("u_width_px", width_px);
    glBindVertexArray(vao_.get());
    glDrawArrays(GL_LINES, 0, static_cast<GLsizei>(segments.size() & ~std::size_t{1}));
    glBindVertexArray(0);
}

}  // namespace pl::app
