// Per-particle instance data shared by the sphere, point-sprite and shadow renderers: one
// upload per frame, three ways to draw it.
#pragma once

#include "app/gl_objects.hpp"

#include <glm/vec4.hpp>

#include <vector>

namespace pl::app {

struct SphereInstance {
    glm::vec4 center_radius;  // m
    glm::vec4 color;          // linear RGBA
};

class InstanceBuffer {
public:
    InstanceBuffer() : buffer_(make_buffer()) {}
    void upload(const std::vector<SphereInstance>& instances);
    GLuint id() const { return buffer_.get(); }
    GLsizei count() const { return count_; }

private:
    GlBuffer buffer_;
    GLsizei count_ = 0;
};

// Points attribute locations 1 (centre, radius) and 2 (colour) of the bound vertex array at the
// instance buffer; `divisor` 1 for instanced meshes, 0 for one point per instance.
void bind_instance_attributes(const InstanceBuffer& instances, GLuint divisor);

}  // namespace pl::app
