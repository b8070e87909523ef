// Events tab: bounces, rests, stops, lifts and freezes as they happened.
#include "physics/stepping/particle_state.hpp"
#include "ui/frame_recorder.hpp"
#include "ui/panel_state.hpp"
#include "ui/sections.hpp"

#include <imgui.h>

#include <vector>

namespace pl::ui {

void draw_events_tab(LabSession& s) {
    PanelState& p = panels_of(s);
    const PlotHistory& h = history_of(s);
    const std::size_t variants = s.experiment->variant_count();
    if (variants > 1) {
        ImGui::SetNextItemWidth(ImGui::GetFontSize() * 10.0f);
        const std::string current = p.events_variant_filter < 0 ? "all variants" : variant_name(s, static_cast<std::size_t>(p.events_variant_filter));
        if (ImGui::BeginCombo("show", current.c_str())) {
            if (ImGui::Selectable("all variants", p.events_variant_filter < 0)) p.events_variant_filter = -1;
            for (std::size_t v = 0; v < variants; ++v)
                if (ImGui::Selectable(variant_name(s, v).c_str(), p.events_variant_filter == static_cast<int>(v)))
                    p.events_variant_filter = static_cast<int>(v);
            ImGui::EndCombo();
        }
        ImGui::SameLine();
    }
    if (p.events_variant_filter >= static_cast<int>(variants)) p.events_variant_filter = -1;
    ImGui::Checkbox("follow newest", &p.events_follow);
    ImGui::SameLine();
    ImGui::TextDisabled("%zu events kept%s", h.events.size(),
                        h.events_dropped ? (", " + std::to_string(h.events_dropped) + " older ones dropped").c_str() : "");

    std::vector<const LoggedEvent*> shown;
    shown.reserve(h.events.size());
    for (const LoggedEvent& e : h.events)
        if (p.events_variant_filter < 0 || e.variant == static_cast<std::uint32_t>(p.events_variant_filter)) shown.push_back(&e);

    const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_Borders | ImGuiTableFlags_ScrollY |
                                  ImGuiTableFlags_SizingStretchProp;
    if (!ImGui::BeginTable("##events", 7, flags, ImVec2(0, ImGui::GetContentRegionAvail().y))) return;
    ImGui::TableSetupScrollFreeze(0, 1);
    ImGui::TableSetupColumn("t (s)");
    ImGui::TableSetupColumn("variant");
    ImGui::TableSetupColumn("particle");
    ImGui::TableSetupColumn("kind");
    ImGui::TableSetupColumn("wall");
    ImGui::TableSetupColumn("speed in (m/s)");
    ImGui::TableSetupColumn("speed out (m/s)");
    ImGui::TableHeadersRow();
    ImGuiListClipper clipper;
    clipper.Begin(static_cast<int>(shown.size()));
    while (clipper.Step()) {
        for (int row = clipper.DisplayStart; row < clipper.DisplayEnd; ++row) {
            const LoggedEvent& le = *shown[static_cast<std::size_t>(row)];
            const Event& e = le.event;
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::Text("%.5f", e.t);
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(variant_name(s, le.variant).c_str());
            ImGui::TableNextColumn();
            ImGui::Text("%u", e.particle);
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(to_string(e.kind));
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(e.wall >= 0 ? wall_name(e.wall) : "-");
            ImGui::TableNextColumn();
            ImGui::Text("%.4g", e.speed_in);
            ImGui::TableNextColumn();
            ImGui::Text("%.4g", e.speed_out);
        }
    }
    if (p.events_follow) ImGui::SetScrollY(ImGui::GetScrollMaxY());
    ImGui::EndTable();
}

}  // namespace pl::ui
