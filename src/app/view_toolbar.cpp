#include "app/view_toolbar.hpp"

#include "app/renderer_arrows.hpp"
#include "app/trail_history.hpp"
#include "app/view_panes.hpp"
#include "ui/sections.hpp"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

namespace pl::app {

namespace {

// A button that stays lit while `on`.
bool toggle_button(const char* label, bool& on, const char* tooltip) {
    const ImVec4 lit(0.24f, 0.42f, 0.64f, 1.0f);
    if (on) {
        ImGui::PushStyleColor(ImGuiCol_Button, lit);
        ImGui::PushStyleColor(ImGuiCol_ButtonHovered, ImVec4(lit.x + 0.05f, lit.y + 0.06f, lit.z + 0.07f, 1.0f));
    }
    const bool pressed = ImGui::Button(label);
    if (on) ImGui::PopStyleColor(2);
    if (pressed) on = !on;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tooltip);
    return pressed;
}

bool view_button(const char* label, const char* tooltip) {
    const bool pressed = ImGui::Button(label);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tooltip);
    return pressed;
}

// Why the wind arrows show nothing or do nothing, if so.
const char* wind_note(const Experiment& e) {
    bool any_wind = false, any_effect = false;
    for (const Simulation& run : e.runs()) {
        const bool wind = run.model().world.wind.kind != WindKind::none;
        any_wind = any_wind || wind;
        any_effect = any_effect || (wind && run.model().drag.model != DragModel::none);
    }
    if (!any_wind) return "\nThis scene has no wind.";
    if (!any_effect) return "\nDrag is off, so the wind has no effect on the particles.";
    return "";
}

bool any_collisions(const Experiment* e) {
    if (!e) return false;
    for (const Simulation& run : e->runs())
        if (run.model().collisions.enabled) return true;
    return false;
}

// The pile's two view options: contacts as lines, sleeping particles tinted. Only with collisions.
void pile_toggles(ui::LabSession& s) {
    const bool off = !any_collisions(s.experiment.get());
    auto explain_if_off = [off] {
        if (off && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
            ImGui::SetTooltip("Contacts and sleeping particles need collisions (Scene section)");
    };
    ImGui::BeginDisabled(off);
    toggle_button("Contacts", s.show_contacts,
                  "Contacts carrying a load, centre to centre (a wall contact: centre to contact point), drawn\n"
                  "through the balls: faint amber for a light load, white for the heaviest in the view");
    ui::note_item_rect(s, "view.contacts");
    explain_if_off();
    ImGui::SameLine();
    toggle_button("Sleep", s.tint_sleeping,
                  "Sleeping particles in slate grey: islands at rest are not stepped until something strikes them");
    ui::note_item_rect(s, "view.sleep");
    explain_if_off();
    ImGui::EndDisabled();
}

// Which variants fill the split view's panes: a checkbox per variant, at most max_split_panes.
void pane_chooser(ui::LabSession& s) {
    const std::size_t count = s.experiment->variant_count();
    const std::vector<std::size_t> shown = split_variants(s.split_variants, count);
    ImGui::SameLine(0.0f, 2.0f);
    const std::string label = std::to_string(shown.size()) + "/" + std::to_string(count) + "###panes";
    if (ImGui::Button(label.c_str())) ImGui::OpenPopup("##pane_choice");
    ui::note_item_rect(s, "view.panes");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Variants shown in the split view (up to %zu)", max_split_panes);
    if (!ImGui::BeginPopup("##pane_choice")) return;
    for (std::size_t v = 0; v < count; ++v) {
        bool on = std::find(shown.begin(), shown.end(), v) != shown.end();
        ImGui::BeginDisabled((!on && shown.size() >= max_split_panes) || (on && shown.size() == 1));
        if (ImGui::Checkbox(ui::variant_name(s, v).c_str(), &on)) {
            std::vector<int> next;
            for (std::size_t k : shown)
                if (k != v) next.push_back(static_cast<int>(k));
            if (on) next.push_back(static_cast<int>(v));
            s.split_variants = next;
        }
        ImGui::EndDisabled();
        ui::note_item_rect(s, "view.pane." + std::to_string(v));
    }
    ImGui::EndPopup();
}

}  // namespace

ViewCommand draw_view_toolbar(ui::LabSession& s, RecordControl& record) {
    ViewCommand cmd;
    char tip[256];
    draw_record_controls(record, s);
    ImGui::SameLine();
    toggle_button("Trails", s.show_trails, "Fading trails of the first particles of each variant and the selected one");
    ImGui::SameLine(0.0f, 2.0f);
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 2.6f);
    if (ImGui::DragInt("##trail_particles", &s.trail_particles, 0.2f, 0, static_cast<int>(TrailHistory::max_per_variant), "%d",
                       ImGuiSliderFlags_AlwaysClamp))
        s.trail_particles = std::clamp(s.trail_particles, 0, static_cast<int>(TrailHistory::max_per_variant));
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Particles of each variant with a trail and a drop line to the floor (drag or double-click to\n"
                          "type; the selected particle always has them)");
    ImGui::SameLine();
    const Room room = s.experiment ? s.experiment->scene().room : Room{};
    std::snprintf(tip, sizeof tip, "Velocity arrows: each shows the distance covered in %.2g s", velocity_arrow_time_s(room));
    toggle_button("Velocity", s.show_velocity, tip);
    ImGui::SameLine();
    std::snprintf(tip, sizeof tip, "Wind field on a grid: each arrow shows the air's travel in %.2g s%s", wind_arrow_time_s(room),
                  s.experiment ? wind_note(*s.experiment) : "");
    toggle_button("Wind", s.show_wind, tip);
    ImGui::SameLine();
    pile_toggles(s);
    ImGui::SameLine();
    const bool single = !s.experiment || s.experiment->variant_count() < 2;
    ImGui::BeginDisabled(single);
    toggle_button("Split", s.split_view, "One pane per variant (up to nine, chosen with the button beside it), same camera");
    ui::note_item_rect(s, "view.split");
    ImGui::EndDisabled();
    if (single && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip("Split view needs a preset with several variants");
    if (s.split_view && !single) pane_chooser(s);
    ImGui::SameLine();
    if (toggle_button("Measure", s.measuring,
                      "M: click two points (a ball, or a trail: the nearest sample) to read the distance and the\n"
                      "time between them; Esc clears"))
        s.measure_points.clear();
    ui::note_item_rect(s, "view.measure");

    ImGui::SameLine(0.0f, 18.0f);
    // The camera buttons in a row when they fit, otherwise behind one "View" button.
    const ImGuiStyle& style = ImGui::GetStyle();
    float row_width = ImGui::CalcTextSize("View").x + style.ItemSpacing.x;
    for (const char* label : {"X", "Y", "Z", "Reset", "Focus"})
        row_width += ImGui::CalcTextSize(label).x + 2.0f * style.FramePadding.x + style.ItemSpacing.x;
    const bool in_row = ImGui::GetContentRegionAvail().x >= row_width;
    if (in_row) {
        ImGui::TextDisabled("View");
        ImGui::SameLine();
    } else {
        if (ImGui::Button("View")) ImGui::OpenPopup("view_menu");
        if (!ImGui::BeginPopup("view_menu")) return cmd;
    }
    auto next = [&] {
        if (in_row) ImGui::SameLine();
    };
    if (view_button("X", "Look along the x axis (key 1; Shift+1 from the other side)")) cmd.axis = 0;
    next();
    if (view_button("Y", "Look down the y axis: top view (key 2; Shift+2 from below)")) cmd.axis = 1;
    next();
    if (view_button("Z", "Look along the z axis: front view (key 3; Shift+3 from behind)")) cmd.axis = 2;
    next();
    if (view_button("Reset", "Frame the whole room (key 0)")) cmd.reset = true;
    next();
    if (view_button("Focus", "Centre the view on the selected particle (key F)")) cmd.focus_selected = true;
    if (!in_row) ImGui::EndPopup();
    return cmd;
}

}  // namespace pl::app
