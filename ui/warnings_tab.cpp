// Warnings tab: every warning every variant raised (once per particle and kind).
#include "ui/sections.hpp"
#include "ui/warning_risk.hpp"

#include <fmt/format.h>

#include <imgui.h>

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

namespace pl::ui {
namespace {

const char* kind_name(WarningKind k) {
    switch (k) {
        case WarningKind::drag_validity: return "drag validity";
        case WarningKind::stability: return "stability";
        case WarningKind::frozen: return "frozen (NaN)";
        case WarningKind::mach: return "Mach number";
        case WarningKind::runaway: return "frozen (runaway speed)";
        case WarningKind::impact_cap: return "frozen (impact cap)";
        case WarningKind::no_rest: return "never rests (explicit Euler)";
        case WarningKind::collision_overlap: return "balls left overlapping";
        case WarningKind::collision_crossing: return "balls crossed in a step";
    }
    return "?";
}
constexpr std::size_t kind_count = warning_kind_count;

struct Row {
    std::size_t variant;
    const Warning* warning;
    bool at_risk;
};

// Rows in variant and time order, warnings at risk before notes, counted per kind.
std::vector<Row> warning_rows(const Experiment& e, std::size_t (&per_kind)[kind_count], std::size_t& notes) {
    std::vector<Row> rows;
    for (std::size_t v = 0; v < e.variant_count(); ++v)
        for (const Warning& w : e.run(v).warnings()) {
            const bool at_risk = puts_number_at_risk(w, e.run(v));
            rows.push_back({v, &w, at_risk});
            if (at_risk) ++per_kind[static_cast<std::size_t>(w.kind)];
            else ++notes;
        }
    std::stable_partition(rows.begin(), rows.end(), [](const Row& r) { return r.at_risk; });
    return rows;
}

// In a scene of thousands of particles, a line per kind first says how many particles share a
// warning, which a scroll through the table cannot.
std::string summary_line(const std::size_t (&per_kind)[kind_count], std::size_t notes) {
    std::string summary;
    for (std::size_t k = 0; k < kind_count; ++k) {
        if (per_kind[k] == 0) continue;
        if (!summary.empty()) summary += "   ";
        summary += std::string(kind_name(static_cast<WarningKind>(k))) + ": " + std::to_string(per_kind[k]) +
                   (per_kind[k] == 1 ? " particle" : " particles");
    }
    if (notes) summary += (summary.empty() ? "No warnings at risk.   notes: " : "   notes: ") + std::to_string(notes);
    return summary;
}

}  // namespace

void draw_warnings_tab(LabSession& s) {
    const Experiment& e = *s.experiment;
    if (warning_count(s) == 0 && note_count(s) == 0) {
        ImGui::TextDisabled("No warnings: every particle stayed within its drag model's validity range, dt is within "
                            "the method's stability limit, and no state became non-finite.");
        return;
    }
    std::size_t per_kind[kind_count] = {};
    std::size_t notes = 0;
    const std::vector<Row> rows = warning_rows(e, per_kind, notes);
    const std::string summary = summary_line(per_kind, notes);
    ImGui::TextUnformatted(summary.c_str());
    if (notes && ImGui::IsItemHovered())
        ImGui::SetTooltip("A note: a particle left its drag model's Reynolds range where the model's drag differs from\n"
                          "the smooth-sphere correlation by less than %.0f%% of gravity, so no number is at risk.",
                          100.0 * negligible_drag_error);
    ImGui::SameLine();
    ImGui::TextDisabled("(once per particle and kind; click a row to inspect the particle)");
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
    // Thousands of particles may each warn once: draw only the visible rows.
    ImGuiListClipper clipper;
    clipper.Begin(static_cast<int>(rows.size()));
    while (clipper.Step()) {
        for (int r = clipper.DisplayStart; r < clipper.DisplayEnd; ++r) {
            const Row& row = rows[static_cast<std::size_t>(r)];
            const std::size_t v = row.variant;
            const Warning& w = *row.warning;
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            const bool selected =
                s.selected_variant == static_cast<int>(v) && s.selected_particle == static_cast<int>(w.particle);
            ImGui::PushID(r);
            if (ImGui::Selectable("##row", selected, ImGuiSelectableFlags_SpanAllColumns)) {
                s.selected_variant = static_cast<int>(v);
                s.selected_particle = static_cast<int>(w.particle);
            }
            if (r == 0) note_item_rect(s, "warnings.row0");
            ImGui::PopID();
            ImGui::SameLine();
            ImGui::Text("%.4f", w.t);
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(variant_name(s, v).c_str());
            ImGui::TableNextColumn();
            ImGui::Text("%u", w.particle);
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(row.at_risk ? kind_name(w.kind) : "note");
            ImGui::TableNextColumn();
            std::string message = warning_message(w, e.run(v).model());
            if (!row.at_risk)
                message += fmt::format("; its drag differs from Cd(Re) by {:.2g}% of gravity: no number at risk",
                                       100.0 * drag_error_fraction(w, e.run(v)));
            ImGui::TextUnformatted(message.c_str());
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", message.c_str());
        }
    }
    ImGui::EndTable();
}

}  // namespace pl::ui
