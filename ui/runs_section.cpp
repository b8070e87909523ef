// The experiment's own panels: what the preset is about (its description in full, its expected
// values beside the measured ones) and the pinned runs kept beside the live one.
#include "ui/expectations_view.hpp"
#include "ui/pinned_runs.hpp"
#include "ui/sections.hpp"

#include <imgui.h>

#include <string>

namespace pl::ui {

void draw_about_section(LabSession& s) {
    if (s.scene.description.empty()) {
        ImGui::TextDisabled("This preset has no description.");
        draw_expectations(s);
        return;
    }
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextUnformatted(s.scene.description.c_str());
    ImGui::PopTextWrapPos();
    draw_expectations(s);
}

void draw_runs_section(LabSession& s) {
    PinBoard& board = pins_of(s);
    if (ImGui::Button("Pin this run")) s.status_message = pin_current_run(s);
    note_item_rect(s, "runs.pin");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("P: keep the selected variant's run as a faded curve in the plots, a ghost path in the\n"
                          "3D view and a row in the Compare tab. Edits, L and R start a new live run beside it.");
    ImGui::SameLine();
    ImGui::BeginDisabled(board.runs.empty());
    if (ImGui::Button("Unpin all")) clear_pins(s);
    ImGui::EndDisabled();
    if (board.runs.empty()) {
        ImGui::TextDisabled("No pinned runs (at most %zu are kept).", PinBoard::max_pins);
        return;
    }
    int remove = 0;
    for (const PinnedRun& run : board.runs) {
        ImGui::PushID(run.number);
        if (ImGui::SmallButton("x")) remove = run.number;
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("Unpin this run");
        ImGui::SameLine();
        const Rgba c = pin_color(run.number, 1.0f);
        ImGui::ColorButton("##c", ImVec4(c[0], c[1], c[2], 1.0f), ImGuiColorEditFlags_NoTooltip, ImVec2(10, 10));
        ImGui::SameLine();
        ImGui::TextUnformatted(run.label.c_str());
        if (ImGui::IsItemHovered()) {
            ImGui::BeginTooltip();
            ImGui::Text("pinned at t = %.3f s", run.t_end);
            for (const RunSetting& setting : run.settings) ImGui::Text("%s: %s", setting.name.c_str(), setting.value.c_str());
            ImGui::EndTooltip();
        }
        ImGui::PopID();
    }
    if (remove) unpin(s, remove);
}

}  // namespace pl::ui
