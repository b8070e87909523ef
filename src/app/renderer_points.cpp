#include "app/renderer_points.hpp"

#include "app/point_splat.hpp"

namespace pl::app {

PointSpriteRenderer::PointSpriteRenderer(const InstanceBuffer& instances)
    : instances_(instances), program_(load_program("point_sprite")), vao_(make_vertex_array()) {
    glBindVertexArray(vao_.get());
    bind_instance_attributes(instances_, 0);
    glBindVertexArray(0);
}

void PointSpriteRenderer::draw(const CameraMatrices& camera, float viewport_height_px) const {
    if (instances_.count() == 0) return;
    program_.use();
    program_.set("u_view", camera.view);
    program_.set("u_proj", camera.proj);
    program_.set("u_viewport_height", viewport_height_px);
    program_.set("u_size_range", glm::vec2(min_point_diameter_px, max_point_diameter_px));
    glEnable(GL_PROGRAM_POINT_SIZE);
    glBindVertexArray(vao_.get());
    glDrawArrays(GL_POINTS, 0, instances_.count());
    glBindVertexArray(0);
    glDisable(GL_PROGRAM_POINT_SIZE);
}

}  // namespace pl::app
