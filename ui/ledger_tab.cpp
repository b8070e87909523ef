// Energy ledger tab: where each variant's energy went, in joules, all particles together.
#include "physics/stepping/energy.hpp"
#include "ui/sections.hpp"

#include <imgui.h>

#include <cmath>

namespace pl::ui {

void draw_ledger_tab(LabSession& s) {
    const Experiment& e = *s.experiment;
    ImGui::TextDisabled("E0 + work by wind = kinetic + potential + lost (bounces, friction, drag) + residual; "
                        "the residual is the integrator's own energy error.");
    const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_Borders | ImGuiTableFlags_ScrollY |
                                  ImGuiTableFlags_ScrollX | ImGuiTableFlags_SizingFixedFit;
    if (!ImGui::BeginTable("##ledger", 10, flags, ImVec2(0, ImGui::GetContentRegionAvail().y))) return;
    ImGui::TableSetupScrollFreeze(1, 1);
    for (const char* name : {"variant", "initial E0", "kinetic", "potential", "lost: bounces", "lost: friction", "lost: drag",
                             "work by wind", "residual", "residual / E0"})
        ImGui::TableSetupColumn(name);
    ImGui::TableHeadersRow();
    for (std::size_t v = 0; v < e.variant_count(); ++v) {
        const Simulation& sim = e.run(v);
        const EnergyBreakdown b = total_energy(sim.state(), sim.model().world.gravity, sim.model().room);
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(variant_name(s, v).c_str());
        for (double value : {b.initial, b.kinetic, b.potential, b.dissipated_bounce, b.dissipated_friction, b.dissipated_drag,
                             b.wind_work, b.residual()}) {
            ImGui::TableNextColumn();
            ImGui::Text("%.6g J", value);
        }
        ImGui::TableNextColumn();
        if (b.initial > 0.0) ImGui::Text("%.2e", b.residual() / b.initial);
        else ImGui::TextUnformatted("-");
    }
    ImGui::EndTable();
}

}  // namespace pl::ui
