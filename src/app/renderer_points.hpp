// Beyond ~1e4 particles: one point sprite per particle, shaded as a sphere.
#pragma once

#include "app/camera.hpp"
#include "app/renderer_instances.hpp"
#include "app/renderer_shader.hpp"

namespace pl::app {

class PointSpriteRenderer {
public:
    explicit PointSpriteRenderer(const InstanceBuffer& instances);
    void draw(const CameraMatrices& camera, float viewport_height_px) const;

private:
    const InstanceBuffer& instances_;
    ShaderProgram program_;
    GlVertexArray vao_;
};

}  // namespace pl::app
