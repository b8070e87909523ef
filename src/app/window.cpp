#include "app/window.hpp"

#include <glad/gl.h>
// glad first: it provides the GL declarations GLFW would otherwise pull in.
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace pl::app {

namespace {

void report_glfw_error(int code, const char* description) {
    std::fprintf(stderr, "particle-lab: GLFW error %d: %s\n", code, description);
}

GLFWwindow* try_create(int width, int height, const std::string& title, int samples) {
    glfwDefaultWindowHints();
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_SAMPLES, samples);
    glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
    glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);  // shown once the final context is settled
    return glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
}

}  // namespace

AppWindow::AppWindow(int width, int height, const std::string& title) {
    glfwSetErrorCallback(report_glfw_error);
    if (!glfwInit()) throw std::runtime_error("cannot initialise GLFW (is a display available?)");
    // Never larger than the screen: the layout is made to fit down to 1280 x 720.
    if (GLFWmonitor* monitor = glfwGetPrimaryMonitor()) {
        if (const GLFWvidmode* mode = glfwGetVideoMode(monitor)) {
            width = std::min(width, mode->width);
            height = std::min(height, mode->height);
        }
    }
    // A CPU rasteriser (llvmpipe under Xvfb or without a GPU driver) pays about twice the frame
    // time for 4x MSAA; lines stay smooth without it (their shader anti-aliases them).
    const bool want_msaa = std::getenv("PL_FORCE_MSAA") != nullptr || !software_renderer();
    if (want_msaa) {
        window_ = try_create(width, height, title, 4);
        if (!window_) glfwSetErrorCallback(nullptr);  // no multisampled visual: fall back quietly
    }
    if (!window_) window_ = try_create(width, height, title, 0);
    glfwSetErrorCallback(report_glfw_error);
    if (!window_) {
        glfwTerminate();
        throw std::runtime_error("cannot create a window with an OpenGL 3.3 core context");
    }
    glfwMakeContextCurrent(window_);
    if (gladLoadGL(glfwGetProcAddress) == 0) {
        glfwDestroyWindow(window_);
        glfwTerminate();
        throw std::runtime_error("cannot load the OpenGL 3.3 functions");
    }
    GLint samples = 0;
    glGetIntegerv(GL_SAMPLES, &samples);
    multisampled_ = samples > 1;
    if (multisampled_) glEnable(GL_MULTISAMPLE);
    glfwSwapInterval(1);
    glfwShowWindow(window_);
}

bool AppWindow::software_renderer() {
    // A hidden probe context, so the real window is created once, with the right visual.
    GLFWwindow* probe = try_create(64, 64, "OpenGL probe", 0);
    if (!probe) return false;
    glfwMakeContextCurrent(probe);
    std::string name;
    if (gladLoadGL(glfwGetProcAddress) != 0) {
        const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
        name = renderer ? renderer : "";
    }
    glfwMakeContextCurrent(nullptr);
    glfwDestroyWindow(probe);
    return is_cpu_rasteriser(name);
}

bool is_cpu_rasteriser(std::string_view gl_renderer) {
    for (const char* cpu : {"llvmpipe", "softpipe", "swrast", "SwiftShader"})
        if (gl_renderer.find(cpu) != std::string_view::npos) return true;
    return false;
}

AppWindow::~AppWindow() {
    glfwDestroyWindow(window_);
    glfwTerminate();
}

}  // namespace pl::app
