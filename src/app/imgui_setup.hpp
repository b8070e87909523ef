// Dear ImGui on the window: GLFW + OpenGL3 backends, the lab's theme and font, imgui.ini in the
// user's config directory so collapsed panels are remembered.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

struct GLFWwindow;

namespace pl::app {

class ImGuiLayer {
public:
    ImGuiLayer(GLFWwindow* window, const std::optional<std::filesystem::path>& config_dir);
    ~ImGuiLayer();
    ImGuiLayer(const ImGuiLayer&) = delete;
    ImGuiLayer& operator=(const ImGuiLayer&) = delete;

    void begin_frame();
    void render();  // draws ImGui's draw data into the current framebuffer

private:
    std::string ini_path_;  // ImGui keeps a pointer to it
};

}  // namespace pl::app
