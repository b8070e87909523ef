#include "app/renderer_splat.hpp"

#include "app/window.hpp"

#include <cstdlib>
#include <string>

namespace pl::app {

namespace {

void texture_parameters() {
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

}  // namespace

SplatRenderer::SplatRenderer()
    : program_(load_program("splat_composite", false, "full_viewport")), vao_(make_vertex_array()), color_(make_texture()),
      depth_(make_texture()) {
    program_.use();
    glUniform1i(program_.uniform("u_color"), 0);
    glUniform1i(program_.uniform("u_depth"), 1);
    glUseProgram(0);
}

void SplatRenderer::upload() {
    const bool resized = image_.width != texture_w_ || image_.height != texture_h_;
    texture_w_ = image_.width;
    texture_h_ = image_.height;
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    // Each image into its texture unit: a new storage when the pane's size changed, else in place.
    auto load = [&](GLenum unit, const GlTexture& texture, GLint internal, GLenum format, GLenum type, const void* pixels) {
        glActiveTexture(unit);
        glBindTexture(GL_TEXTURE_2D, texture.get());
        if (resized) {
            texture_parameters();
            glTexImage2D(GL_TEXTURE_2D, 0, internal, texture_w_, texture_h_, 0, format, type, pixels);
        } else {
            glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, texture_w_, texture_h_, format, type, pixels);
        }
    };
    load(GL_TEXTURE1, depth_, GL_R32F, GL_RED, GL_FLOAT, image_.depth.data());
    load(GL_TEXTURE0, color_, GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, image_.rgba.data());
}

void SplatRenderer::draw(const std::vector<SphereInstance>& instances, const CameraMatrices& camera, int x, int y,
                         int w, int h) {
    if (instances.empty() || w <= 0 || h <= 0) return;
    splat_points(instances, camera.view, camera.proj, w, h, image_);
    upload();
    program_.use();
    glUniform2i(program_.uniform("u_origin"), x, y);
    glBindVertexArray(vao_.get());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glBindTexture(GL_TEXTURE_2D, 0);
}

bool splat_points_on_cpu(const char* gl_renderer) {
    if (const char* forced = std::getenv("PL_POINT_SPLAT"); forced && *forced) return std::string(forced) != "0";
    return gl_renderer != nullptr && is_cpu_rasteriser(gl_renderer);
}

}  // namespace pl::app
