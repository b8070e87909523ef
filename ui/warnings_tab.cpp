// Warnings tab: every warning every variant raised (once per particle and kind).
#include "ui/sections.hpp"

#include <imgui.h>

namespace pl::ui {
namespace {

const char* kind_name(WarningKind k) {
    switch (k) {
        case WarningKind::drag_validity: return "drag validity";
        case WarningKind::stability: return "stability";
        case WarningKind::frozen: return "frozen (NaN)";
        case WarningKind::mach: return "Mach number";
    }
    return "?";
}

}  // namespace

void draw_warnings_tab(LabSession& s) {
    const Experiment& e = *s.experiment;
    if (warning_count(s) == 0) {
        ImGui::TextDisabled("No warnings: every particle stayed within its drag model's validity range, dt is within "
                            "the method's stability limit, and no state became non-finite.");
        return;
    }
    const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_Borders | ImGuiTableFlags_ScrollY |
                                  ImGuiTableFlags_SizingStretchProp;
    if (!ImGui::BeginTable("##warnings", 5, flags, ImVec2(0, ImGui::GetContentRegionAvail().y))) return;
    ImGui::TableSetupScrollFreeze(0, 1);
    ImGui::TableSetupColumn("t (s)", ImGuiTableColumnFlags_WidthFixed);
    ImGui::TableSetupColumn("variant", ImGuiTableColumnFlags_WidthFixed);
    ImGui::TableSetupColumn("particle", ImGuiTableColumnFlags_WidthFixed);
    ImGui::TableSetupColumn("kind", ImGuiTableColumnFlags_WidthFixed);
    ImGui::TableSetupColumn("message", ImGuiTableColumnFlags_WidthStretch);
    ImGui::TableHeadersRow();
    for (std::size_t v = 0; v < e.variant_count(); ++v) {
        for (const Warning& w : e.run(v).warnings()) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::Text("%.4f", w.t);
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(variant_name(s, v).c_str());
            ImGui::TableNextColumn();
            ImGui::Text("%u", w.particle);
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(kind_name(w.kind));
            ImGui::TableNextColumn();
            ImGui::TextWrapped("%s", w.message.c_str());
        }
    }
    ImGui::EndTable();
}

}  // namespace pl::ui
