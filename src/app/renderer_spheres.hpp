// Lit spheres drawn instanced from one mesh (up to ~1e4 particles).
#pragma once

#include "app/camera.hpp"
#include "app/renderer_instances.hpp"
#include "app/renderer_shader.hpp"

namespace pl::app {

class SphereRenderer {
public:
    explicit SphereRenderer(const InstanceBuffer& instances);
    // Spheres smaller than `min_radius_per_depth` x depth are drawn that large.
    void draw(const CameraMatrices& camera, float min_radius_per_depth) const;

private:
    const InstanceBuffer& instances_;
    ShaderProgram program_;
    GlVertexArray vao_;
    GlBuffer vertices_, indices_;
    GLsizei index_count_ = 0;
};

}  // namespace pl::app
