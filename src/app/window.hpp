// The GLFW window with an OpenGL 3.3 core context and the glad loader. 4x MSAA when the system
// offers it, except on a CPU rasteriser (set PL_FORCE_MSAA to have it there too, e.g. for
// screenshots).
#pragma once

#include <string>
#include <string_view>

struct GLFWwindow;

namespace pl::app {

// Whether an OpenGL GL_RENDERER string names a CPU rasteriser (Mesa's llvmpipe or softpipe,
// SwiftShader): one where every vertex and pixel costs CPU time the physics could use.
bool is_cpu_rasteriser(std::string_view gl_renderer);

class AppWindow {
public:
    // Throws std::runtime_error when no window or no OpenGL 3.3 context can be created.
    AppWindow(int width, int height, const std::string& title);
    ~AppWindow();
    AppWindow(const AppWindow&) = delete;
    AppWindow& operator=(const AppWindow&) = delete;

    GLFWwindow* handle() const { return window_; }
    bool multisampled() const { return multisampled_; }

private:
    static bool software_renderer();  // a CPU rasteriser such as Mesa's llvmpipe

    GLFWwindow* window_ = nullptr;
    bool multisampled_ = false;
};

}  // namespace pl::app
