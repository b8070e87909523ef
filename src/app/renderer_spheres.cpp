#include "app/renderer_spheres.hpp"

#include "app/renderer_sphere_mesh.hpp"

#include <glm/geometric.hpp>

#include <cstdint>

namespace pl::app {

namespace {

// Icosphere subdivisions by sphere count: 1280, 320 and 80 triangles per sphere.
struct LodSpec {
    int subdivisions;
    std::size_t max_instances;
};
constexpr std::array<LodSpec, 3> lod_specs{{{3, 300}, {2, 2500}, {1, SIZE_MAX}}};

}  // namespace

SphereRenderer::SphereRenderer(const InstanceBuffer& instances)
    : instances_(instances), program_(load_program("sphere")), vao_(make_vertex_array()), vertices_(make_buffer()),
      indices_(make_buffer()) {
    std::vector<glm::vec3> vertices;
    std::vector<std::uint32_t> indices;
    for (std::size_t k = 0; k < lod_specs.size(); ++k) {
        const UnitSphereMesh mesh = make_unit_icosphere(lod_specs[k].subdivisions);
        lods_[k] = {lod_specs[k].max_instances, static_cast<GLsizei>(mesh.indices.size()), indices.size(),
                    static_cast<GLint>(vertices.size())};
        vertices.insert(vertices.end(), mesh.vertices.begin(), mesh.vertices.end());
        indices.insert(indices.end(), mesh.indices.begin(), mesh.indices.end());
    }
    glBindVertexArray(vao_.get());
    glBindBuffer(GL_ARRAY_BUFFER, vertices_.get());
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(glm::vec3)), vertices.data(),
                 GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices_.get());
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(indices.size() * sizeof(std::uint32_t)),
                 indices.data(), GL_STATIC_DRAW);
    bind_instance_attributes(instances_, 1);
    glBindVertexArray(0);
}

void SphereRenderer::draw(const CameraMatrices& camera, float min_radius_per_depth) const {
    const auto count = static_cast<std::size_t>(instances_.count());
    if (count == 0) return;
    const Lod* lod = &lods_.back();
    for (const Lod& l : lods_)
        if (count <= l.max_instances) {
            lod = &l;
            break;
        }
    program_.use();
    program_.set("u_view_proj", camera.view_proj);
    program_.set("u_eye", camera.eye);
    program_.set("u_forward", camera.forward);
    program_.set("u_min_radius_per_depth", min_radius_per_depth);
    program_.set("u_light_dir", glm::normalize(glm::vec3(0.45f, 1.0f, 0.35f)));
    glBindVertexArray(vao_.get());
    glDrawElementsInstancedBaseVertex(GL_TRIANGLES, lod->index_count, GL_UNSIGNED_INT,
                                      reinterpret_cast<const void*>(lod->first_index * sizeof(std::uint32_t)),
                                      instances_.count(), lod->base_vertex);
    glBindVertexArray(0);
}

}  // namespace pl::app
