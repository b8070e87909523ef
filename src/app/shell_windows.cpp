#include "app/shell_windows.hpp"

#include "app/view_toolbar.hpp"
#include "ui/lab_ui.hpp"

#include <imgui.h>

namespace pl::app {

namespace {

constexpr ImGuiWindowFlags fixed_flags =
    ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoBringToFrontOnFocus;
constexpr ImGuiWindowFlags bar_flags = fixed_flags | ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoScrollbar |
                                       ImGuiWindowFlags_NoScrollWithMouse | ImGuiWindowFlags_NoSavedSettings |
                                       ImGuiWindowFlags_NoCollapse;
constexpr float bar_padding_y = 5.0f;

void place_next(const Rect& r) {
    ImGui::SetNextWindowPos(ImVec2(r.x, r.y), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(r.w, r.h), ImGuiCond_Always);
}

// A collapsible panel: `draw` fills it while expanded. Returns whether it is collapsed now.
template <typename Draw>
bool panel(const char* title, const Rect& r, Draw&& draw) {
    place_next(r);
    const bool open = ImGui::Begin(title, nullptr, fixed_flags);
    const bool collapsed = ImGui::IsWindowCollapsed();
    if (open) draw();
    ImGui::End();
    return collapsed;
}

}  // namespace

LayoutMetrics layout_metrics() {
    LayoutMetrics m;
    m.title_bar_h = ImGui::GetFrameHeight();
    m.toolbar_h = ImGui::GetFrameHeight() + 2.0f * bar_padding_y;
    m.status_h = ImGui::GetTextLineHeight() + 2.0f * bar_padding_y + 2.0f;
    return m;
}

ViewCommand draw_shell_windows(ui::LabSession& s, const ShellLayout& l, PanelCollapse& collapsed, RecordControl& record) {
    s.widget_rects.clear();  // this frame's panels note theirs again
    collapsed.controls = panel("Experiment###controls", l.controls, [&] { ui::draw_control_panel(s); });
    collapsed.plots = panel("Plots###plots", l.plots, [&] { ui::draw_plots_panel(s); });
    collapsed.analysis = panel("Analysis###analysis", l.analysis, [&] { ui::draw_analysis_panel(s); });

    ViewCommand cmd;
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(8.0f, bar_padding_y));
    place_next(l.toolbar);
    if (ImGui::Begin("##view_toolbar", nullptr, bar_flags)) cmd = draw_view_toolbar(s, record);
    ImGui::End();
    place_next(l.status);
    if (ImGui::Begin("##status_bar", nullptr, bar_flags)) ui::draw_status_bar(s);
    ImGui::End();
    ImGui::PopStyleVar();
    return cmd;
}

}  // namespace pl::app
