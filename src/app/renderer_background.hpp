// Vertical gradient behind the room.
#pragma once

#include "app/renderer_shader.hpp"

namespace pl::app {

class BackgroundRenderer {
public:
    BackgroundRenderer();
    void draw() const;

private:
    ShaderProgram program_;
    GlVertexArray vao_;  // core profile needs one bound even without attributes
};

}  // namespace pl::app
