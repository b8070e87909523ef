// Soft contact shadows on the floor under each sphere (a depth cue: where is it above the floor).
#pragma once

#include "app/camera.hpp"
#include "app/renderer_instances.hpp"
#include "app/renderer_shader.hpp"

namespace pl::app {

class ShadowRenderer {
public:
    explicit ShadowRenderer(const InstanceBuffer& instances);
    void draw(const CameraMatrices& camera, float floor_y, float min_radius_per_depth) const;

private:
    const InstanceBuffer& instances_;
    ShaderProgram program_;
    GlVertexArray vao_;
    GlBuffer corners_;
};

}  // namespace pl::app
