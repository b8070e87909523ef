#include "app/renderer_spheres.hpp"

#include "app/renderer_sphere_mesh.hpp"

#include <glm/geometric.hpp>

namespace pl::app {

SphereRenderer::SphereRenderer(const InstanceBuffer& instances)
    : instances_(instances), program_(load_program("sphere")), vao_(make_vertex_array()), vertices_(make_buffer()),
      indices_(make_buffer()) {
    const UnitSphereMesh mesh = make_unit_icosphere(3);
    index_count_ = static_cast<GLsizei>(mesh.indices.size());
    glBindVertexArray(vao_.get());
    glBindBuffer(GL_ARRAY_BUFFER, vertices_.get());
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.vertices.size() * sizeof(glm::vec3)),
                 mesh.vertices.data(), GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices_.get());
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.indices.size() * sizeof(std::uint32_t)),
                 mesh.indices.data(), GL_STATIC_DRAW);
    bind_instance_attributes(instances_, 1);
    glBindVertexArray(0);
}

void SphereRenderer::draw(const CameraMatrices& camera, float min_radius_per_depth) const {
    if (instances_.count() == 0) return;
    program_.use();
    program_.set("u_view_proj", camera.view_proj);
    program_.set("u_eye", camera.eye);
    program_.set("u_forward", camera.forward);
    program_.set("u_min_radius_per_depth", min_radius_per_depth);
    program_.set("u_light_dir", glm::normalize(glm::vec3(0.45f, 1.0f, 0.35f)));
    glBindVertexArray(vao_.get());
    glDrawElementsInstanced(GL_TRIANGLES, index_count_, GL_UNSIGNED_INT, nullptr, instances_.count());
    glBindVertexArray(0);
}

}  // namespace pl::app
