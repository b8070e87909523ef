#include "app/imgui_setup.hpp"

#include "app/config_dir.hpp"

#include <glad/gl.h>
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <algorithm>
#include <filesystem>
#include <optional>

namespace pl::app {

namespace {

// A sans-serif face reads far better than ImGui's bitmap font; use it when the system has it.
constexpr const char* ui_font_candidates[] = {
    "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf",
    "/usr/share/fonts/TTF/DejaVuSans.ttf",
};

void load_font(float scale) {
    ImGuiIO& io = ImGui::GetIO();
    std::error_code ec;
    for (const char* path : ui_font_candidates) {
        if (std::filesystem::is_regular_file(path, ec) && io.Fonts->AddFontFromFileTTF(path, 15.0f * scale)) return;
    }
    ImFontConfig config;
    config.SizePixels = 13.0f * scale;
    io.Fonts->AddFontDefault(&config);
}

// Dark, low-contrast chrome so the data (3D view, plot lines) carries the colour.
void apply_lab_style(float scale) {
    ImGui::StyleColorsDark();
    ImGuiStyle& st = ImGui::GetStyle();
    st.WindowRounding = 0.0f;
    st.ChildRounding = 3.0f;
    st.FrameRounding = 3.0f;
    st.PopupRounding = 3.0f;
    st.GrabRounding = 3.0f;
    st.TabRounding = 3.0f;
    st.ScrollbarRounding = 3.0f;
    st.WindowBorderSize = 1.0f;
    st.FrameBorderSize = 0.0f;
    st.WindowPadding = ImVec2(10, 8);
    st.FramePadding = ImVec2(6, 3);
    st.ItemSpacing = ImVec2(8, 5);
    st.ItemInnerSpacing = ImVec2(5, 4);
    st.ScrollbarSize = 12.0f;
    st.GrabMinSize = 10.0f;
    st.WindowTitleAlign = ImVec2(0.0f, 0.5f);

    ImVec4* c = st.Colors;
    const ImVec4 bg(0.105f, 0.115f, 0.135f, 1.0f);
    const ImVec4 panel(0.125f, 0.135f, 0.158f, 1.0f);
    const ImVec4 accent(0.31f, 0.61f, 0.91f, 1.0f);
    c[ImGuiCol_WindowBg] = panel;
    c[ImGuiCol_ChildBg] = ImVec4(0, 0, 0, 0);
    c[ImGuiCol_PopupBg] = ImVec4(0.14f, 0.15f, 0.18f, 0.98f);
    c[ImGuiCol_Border] = ImVec4(0.22f, 0.24f, 0.28f, 1.0f);
    c[ImGuiCol_TitleBg] = bg;
    c[ImGuiCol_TitleBgActive] = bg;
    c[ImGuiCol_TitleBgCollapsed] = bg;
    c[ImGuiCol_MenuBarBg] = bg;
    c[ImGuiCol_FrameBg] = ImVec4(0.18f, 0.195f, 0.23f, 1.0f);
    c[ImGuiCol_FrameBgHovered] = ImVec4(0.23f, 0.25f, 0.30f, 1.0f);
    c[ImGuiCol_FrameBgActive] = ImVec4(0.26f, 0.29f, 0.35f, 1.0f);
    c[ImGuiCol_Button] = ImVec4(0.20f, 0.22f, 0.27f, 1.0f);
    c[ImGuiCol_ButtonHovered] = ImVec4(0.27f, 0.31f, 0.39f, 1.0f);
    c[ImGuiCol_ButtonActive] = ImVec4(accent.x, accent.y, accent.z, 0.8f);
    c[ImGuiCol_Header] = ImVec4(0.20f, 0.23f, 0.29f, 1.0f);
    c[ImGuiCol_HeaderHovered] = ImVec4(0.26f, 0.30f, 0.38f, 1.0f);
    c[ImGuiCol_HeaderActive] = ImVec4(0.29f, 0.34f, 0.44f, 1.0f);
    c[ImGuiCol_Tab] = ImVec4(0.16f, 0.175f, 0.21f, 1.0f);
    c[ImGuiCol_TabHovered] = ImVec4(0.28f, 0.33f, 0.42f, 1.0f);
    c[ImGuiCol_TabActive] = ImVec4(0.23f, 0.27f, 0.35f, 1.0f);
    c[ImGuiCol_TabUnfocused] = c[ImGuiCol_Tab];
    c[ImGuiCol_TabUnfocusedActive] = c[ImGuiCol_TabActive];
    c[ImGuiCol_CheckMark] = accent;
    c[ImGuiCol_SliderGrab] = ImVec4(accent.x, accent.y, accent.z, 0.85f);
    c[ImGuiCol_SliderGrabActive] = accent;
    c[ImGuiCol_Separator] = c[ImGuiCol_Border];
    c[ImGuiCol_PlotLines] = accent;
    c[ImGuiCol_TextSelectedBg] = ImVec4(accent.x, accent.y, accent.z, 0.35f);
    c[ImGuiCol_Text] = ImVec4(0.88f, 0.89f, 0.91f, 1.0f);
    c[ImGuiCol_TextDisabled] = ImVec4(0.52f, 0.55f, 0.60f, 1.0f);
    st.ScaleAllSizes(scale);
}

}  // namespace

ImGuiLayer::ImGuiLayer(GLFWwindow* window, const std::optional<std::filesystem::path>& config_dir) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    // imgui.ini is a few kB; one that is not a regular file of sane size (a FIFO hung start-up)
    // is neither read nor overwritten: the layout is then simply not remembered.
    constexpr std::uintmax_t max_ini_bytes = 1 << 20;
    const auto ini = config_dir ? std::optional(*config_dir / "imgui.ini") : std::nullopt;
    std::error_code ec;
    if (ini && (!std::filesystem::exists(std::filesystem::symlink_status(*ini, ec)) ||
                readable_settings_file(*ini, max_ini_bytes))) {
        ini_path_ = ini->string();
        io.IniFilename = ini_path_.c_str();
    } else {
        io.IniFilename = nullptr;
    }
    float scale_x = 1.0f, scale_y = 1.0f;
    glfwGetWindowContentScale(window, &scale_x, &scale_y);
    const float scale = std::clamp(std::max(scale_x, scale_y), 1.0f, 3.0f);
    apply_lab_style(scale);
    load_font(scale);
    ImGui_ImplGlfw_InitForOpenGL(window, true);  // chains to callbacks installed before it
    ImGui_ImplOpenGL3_Init("#version 330");
}

ImGuiLayer::~ImGuiLayer() {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
}

void ImGuiLayer::begin_frame() {
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
}

void ImGuiLayer::render() {
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

}  // namespace pl::app
