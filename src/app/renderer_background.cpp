#include "app/renderer_background.hpp"

namespace pl::app {

BackgroundRenderer::BackgroundRenderer() : program_(load_program("background", false, "full_viewport")), vao_(make_vertex_array()) {}

void BackgroundRenderer::draw() const {
    program_.use();
    program_.set("u_top", glm::vec3(0.135f, 0.150f, 0.180f));
    program_.set("u_bottom", glm::vec3(0.060f, 0.066f, 0.078f));
    glDisable(GL_DEPTH_TEST);
    glBindVertexArray(vao_.get());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glEnable(GL_DEPTH_TEST);
}

}  // namespace pl::app
