#include "app/renderer_shadows.hpp"

#include <glm/vec2.hpp>

#include <array>

namespace pl::app {

ShadowRenderer::ShadowRenderer(const InstanceBuffer& instances)
    : instances_(instances), program_(load_program("shadow")), vao_(make_vertex_array()), corners_(make_buffer()) {
    const std::array<glm::vec2, 4> quad{glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(-1, 1), glm::vec2(1, 1)};
    glBindVertexArray(vao_.get());
    glBindBuffer(GL_ARRAY_BUFFER, corners_.get());
    glBufferData(GL_ARRAY_BUFFER, sizeof(quad), quad.data(), GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, sizeof(glm::vec2), nullptr);
    bind_instance_attributes(instances_, 1);
    glDisableVertexAttribArray(2);  // shadows ignore the colour
    glBindVertexArray(0);
}

void ShadowRenderer::draw(const CameraMatrices& camera, float floor_y, float min_radius_per_depth) const {
    if (instances_.count() == 0) return;
    program_.use();
    program_.set("u_view_proj", camera.view_proj);
    program_.set("u_floor_y", floor_y);
    program_.set("u_eye", camera.eye);
    program_.set("u_forward", camera.forward);
    program_.set("u_min_radius_per_depth", min_radius_per_depth);
    glBindVertexArray(vao_.get());
    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, instances_.count());
    glBindVertexArray(0);
}

}  // namespace pl::app
