// Shader programs loaded from the shaders/ directory (one GLSL file per stage).
#pragma once

#include "app/gl_objects.hpp"

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <filesystem>
#include <string>

namespace pl::app {

// The directory holding the GLSL files: shaders/ in the data folder (app/data_dir.hpp).
std::filesystem::path shader_directory();

class ShaderProgram {
public:
    ShaderProgram() = default;
    explicit ShaderProgram(GlProgram program) : program_(std::move(program)) {}

    void use() const { glUseProgram(program_.get()); }
    GLint uniform(const char* name) const { return glGetUniformLocation(program_.get(), name); }
    void set(const char* name, const glm::mat4& m) const;
    void set(const char* name, const glm::vec3& v) const;
    void set(const char* name, const glm::vec2& v) const;
    void set(const char* name, float f) const;

private:
    GlProgram program_;
};

// Compiles and links `<name>.vert` (or `<vertex>.vert`, a vertex stage programs share), `<name>.frag`
// and, when `with_geometry`, `<name>.geom`. Throws std::runtime_error naming the file and carrying
// the driver's log on failure.
ShaderProgram load_program(const std::string& name, bool with_geometry = false, const std::string& vertex = {});

}  // namespace pl::app
