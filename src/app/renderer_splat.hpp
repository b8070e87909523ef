// Many particles on a CPU rasteriser: splatted into an image on the CPU (app/point_splat.hpp),
// then drawn as one full-pane triangle that writes each pixel's colour and depth. What a GPU
// does with point sprites at no cost, llvmpipe does at 0.5 us a point on one thread; this path
// costs a few milliseconds a frame for 1e5 particles.
#pragma once

#include "app/camera.hpp"
#include "app/point_splat.hpp"
#include "app/renderer_shader.hpp"


namespace pl::app {

class SplatRenderer {
public:
    SplatRenderer();
    // Draws `instances` into the pane whose lower-left corner is (x, y) in window pixels; the
    // viewport and scissor are the pane's.
    void draw(const std::vector<SphereInstance>& instances, const CameraMatrices& camera, int x, int y, int w, int h);

private:
    void upload();

    SplatImage image_;
    ShaderProgram program_;
    GlVertexArray vao_;
    GlTexture color_, depth_;
    int texture_w_ = 0, texture_h_ = 0;
};

// Whether many particles are splatted on the CPU: on a CPU rasteriser, by the GL_RENDERER string
// of the current context (llvmpipe, softpipe, ...). PL_POINT_SPLAT=1 or 0 forces the choice.
bool splat_points_on_cpu(const char* gl_renderer);  // null: not known, not a CPU rasteriser

}  // namespace pl::app
