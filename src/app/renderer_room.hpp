// The room: translucent walls drawn from the inside only (the walls between the camera and the
// room are culled, so the inside stays visible), the floor grid and the box edges.
#pragma once

#include "app/camera.hpp"
#include "app/renderer_lines.hpp"
#include "app/renderer_shader.hpp"
#include "physics/model/scene.hpp"

namespace pl::app {

struct GridSpacing {
    double major = 1.0;  // m: labelled lines
    double minor = 0.5;  // m: faint lines, 0 for none
};
// 1 m lines for rooms of everyday size; a 1-2-5 step keeping 2..50 lines otherwise.
GridSpacing floor_grid_spacing(const Room& room);

class RoomRenderer {
public:
    RoomRenderer();
    void draw_walls(const Room& room, const CameraMatrices& camera);
    static void append_floor_grid(const Room& room, LineSegments& out);
    static void append_edges(const Room& room, LineSegments& out);

private:
    ShaderProgram program_;
    GlVertexArray vao_;
    GlBuffer buffer_;
};

}  // namespace pl::app
