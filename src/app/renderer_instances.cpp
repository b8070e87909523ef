#include "app/renderer_instances.hpp"

#include <cstddef>

namespace pl::app {

void InstanceBuffer::upload(const std::vector<SphereInstance>& instances) {
    upload_stream(GL_ARRAY_BUFFER, buffer_.get(), instances.data(), instances.size() * sizeof(SphereInstance));
    count_ = static_cast<GLsizei>(instances.size());
}

void bind_instance_attributes(const InstanceBuffer& instances, GLuint divisor) {
    glBindBuffer(GL_ARRAY_BUFFER, instances.id());
    const auto stride = static_cast<GLsizei>(sizeof(SphereInstance));
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, stride,
                          reinterpret_cast<const void*>(offsetof(SphereInstance, center_radius)));
    glVertexAttribDivisor(1, divisor);
    glEnableVertexAttribArray(2);
    glVertexAttribPointer(2, 4, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<const void*>(offsetof(SphereInstance, color)));
    glVertexAttribDivisor(2, divisor);
}

}  // namespace pl::app
