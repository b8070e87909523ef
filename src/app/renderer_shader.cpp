#include "app/renderer_shader.hpp"

#include "app/data_dir.hpp"

#include <glm/gtc/type_ptr.hpp>

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace pl::app {

namespace {

std::string read_text(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw std::runtime_error("cannot read shader " + file.string());
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

GLuint compile_stage(GLenum stage, const std::filesystem::path& file) {
    const std::string source = read_text(file);
    const GLuint shader = glCreateShader(stage);
    const char* text = source.c_str();
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (ok != GL_TRUE) {
        GLint length = 0;
        glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
        std::vector<char> log(static_cast<std::size_t>(length) + 1, '\0');
        glGetShaderInfoLog(shader, length, nullptr, log.data());
        glDeleteShader(shader);
        throw std::runtime_error("shader " + file.string() + " does not compile:\n" + log.data());
    }
    return shader;
}

}  // namespace

std::filesystem::path shader_directory() { return data_path("shaders"); }

ShaderProgram load_program(const std::string& name, bool with_geometry, const std::string& vertex) {
    const std::filesystem::path dir = shader_directory();
    std::vector<GLuint> stages;
    try {
        stages.push_back(compile_stage(GL_VERTEX_SHADER, dir / ((vertex.empty() ? name : vertex) + ".vert")));
        if (with_geometry) stages.push_back(compile_stage(GL_GEOMETRY_SHADER, dir / (name + ".geom")));
        stages.push_back(compile_stage(GL_FRAGMENT_SHADER, dir / (name + ".frag")));
    } catch (...) {
        for (GLuint s : stages) glDeleteShader(s);
        throw;
    }
    GlProgram program(glCreateProgram());
    for (GLuint s : stages) glAttachShader(program.get(), s);
    glLinkProgram(program.get());
    for (GLuint s : stages) glDeleteShader(s);
    GLint ok = GL_FALSE;
    glGetProgramiv(program.get(), GL_LINK_STATUS, &ok);
    if (ok != GL_TRUE) {
        GLint length = 0;
        glGetProgramiv(program.get(), GL_INFO_LOG_LENGTH, &length);
        std::vector<char> log(static_cast<std::size_t>(length) + 1, '\0');
        glGetProgramInfoLog(program.get(), length, nullptr, log.data());
        throw std::runtime_error("shader program " + (dir / name).string() + " does not link:\n" + log.data());
    }
    return ShaderProgram(std::move(program));
}

void ShaderProgram::set(const char* name, const glm::mat4& m) const {
    glUniformMatrix4fv(uniform(name), 1, GL_FALSE, glm::value_ptr(m));
}
void ShaderProgram::set(const char* name, const glm::vec3& v) const { glUniform3fv(uniform(name), 1, glm::value_ptr(v)); }
void ShaderProgram::set(const char* name, const glm::vec2& v) const { glUniform2fv(uniform(name), 1, glm::value_ptr(v)); }
void ShaderProgram::set(const char* name, float f) const { glUniform1f(uniform(name), f); }

}  // namespace pl::app
