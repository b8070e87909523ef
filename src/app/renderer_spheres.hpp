// Lit spheres drawn instanced from one mesh (up to ~1e4 particles). The mesh is coarser the more
// spheres there are, so the triangle count stays bounded (a CPU rasteriser must cope too).
#pragma once

#include "app/camera.hpp"
#include "app/renderer_instances.hpp"
#include "app/renderer_shader.hpp"

#include <array>

namespace pl::app {

class SphereRenderer {
public:
    explicit SphereRenderer(const InstanceBuffer& instances);
    // Spheres smaller than `min_radius_per_depth` x depth are drawn that large.
    void draw(const CameraMatrices& camera, float min_radius_per_depth) const;

private:
    struct Lod {
        std::size_t max_instances;  // use this mesh up to this many spheres
        GLsizei index_count;
        std::size_t first_index;
        GLint base_vertex;
    };

    const InstanceBuffer& instances_;
    ShaderProgram program_;
    GlVertexArray vao_;
    GlBuffer vertices_, indices_;
    std::array<Lod, 3> lods_{};
};

}  // namespace pl::app
