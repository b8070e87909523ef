// The GLFW window with an OpenGL 3.3 core context (4x MSAA when the system offers it) and the
// glad loader.
#pragma once

#include <string>

struct GLFWwindow;

namespace pl::app {

class AppWindow {
public:
    // Throws std::runtime_error when no window or no OpenGL 3.3 context can be created.
    AppWindow(int width, int height, const std::string& title);
    ~AppWindow();
    AppWindow(const AppWindow&) = delete;
    AppWindow& operator=(const AppWindow&) = delete;

    GLFWwindow* handle() const { return window_; }
    bool multisampled() const { return multisampled_; }

    bool software_renderer() const;  // a CPU rasteriser such as Mesa's llvmpipe

private:
    void load_gl();

    GLFWwindow* window_ = nullptr;
    bool multisampled_ = false;
};

}  // namespace pl::app
