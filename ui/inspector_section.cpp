#include "physics/stepping/energy.hpp"
#include "ui/palette.hpp"
#include "ui/sections.hpp"

#include <imgui.h>

#include <algorithm>
#include <string>

namespace pl::ui {

void draw_inspector_section(LabSession& s) {
    if (!s.experiment || s.experiment->variant_count() == 0) return;
    const Experiment& e = *s.experiment;
    const std::size_t variants = e.variant_count();
    if (s.selected_variant < 0 || static_cast<std::size_t>(s.selected_variant) >= variants) s.selected_variant = 0;
    const std::size_t v = static_cast<std::size_t>(s.selected_variant);
    const Simulation& sim = e.run(v);
    const std::size_t n = sim.particle_count();
    if (n == 0) {
        ImGui::TextDisabled("no particles");
        return;
    }
    if (variants > 1) {
        if (ImGui::BeginCombo("variant", variant_name(s, v).c_str())) {
            for (std::size_t k = 0; k < variants; ++k)
                if (ImGui::Selectable(variant_name(s, k).c_str(), k == v)) s.selected_variant = static_cast<int>(k);
            ImGui::EndCombo();
        }
    }
    int particle = s.selected_particle;
    if (ImGui::InputInt("particle", &particle)) s.selected_particle = std::clamp(particle, 0, static_cast<int>(n) - 1);
    if (s.selected_particle < 0 || static_cast<std::size_t>(s.selected_particle) >= n) s.selected_particle = 0;
    const std::size_t i = static_cast<std::size_t>(s.selected_particle);

    const ParticleState& st = sim.state();
    const Model& m = sim.model();
    const Rgba c = series_color(color_index(v, i, variants));
    ImGui::ColorButton("##c", ImVec4(c[0], c[1], c[2], 1.0f), ImGuiColorEditFlags_NoTooltip, ImVec2(12, 12));
    ImGui::SameLine();
    ImGui::Text("particle %zu of %zu", i, n);
    ImGui::Text("mass %.4g kg   radius %.4g m", st.mass[i], st.radius[i]);
    const Vec3 x = st.position(i), vel = st.velocity(i);
    ImGui::Text("position  (%.4f, %.4f, %.4f) m", x.x, x.y, x.z);
    ImGui::Text("velocity  (%.4f, %.4f, %.4f) m/s", vel.x, vel.y, vel.z);
    ImGui::Text("speed %.4f m/s   height %.4f m", glm::length(vel), x.y - m.room.floor_y());
    const Vec3 a = sim.acceleration(i);
    ImGui::Text("acceleration (%.3f, %.3f, %.3f) m/s²", a.x, a.y, a.z);
    std::string walls;
    for (int w = 0; w < wall_count; ++w)
        if (st.resting[i] & (1u << w)) walls += std::string(walls.empty() ? "" : ", ") + wall_name(w);
    ImGui::Text("resting on: %s", walls.empty() ? "nothing (in flight)" : walls.c_str());
    if (st.frozen[i]) ImGui::TextColored({1.0f, 0.4f, 0.4f, 1.0f}, "FROZEN: its state became non-finite");
    if (m.drag.model != DragModel::none) {
        const ReRange seen = sim.observed_reynolds();
        ImGui::Text("Reynolds number %.3g", sim.reynolds_number(i));
        // On a line of its own: beside the particle's number it ran past the panel's edge.
        if (seen.lo <= seen.hi) ImGui::TextDisabled("  scene so far: %.3g .. %.3g", seen.lo, seen.hi);
    }

    const EnergyBreakdown en = particle_energy(st, i, m.world.gravity, m.room);
    if (ImGui::BeginTable("energy", 2, ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_RowBg)) {
        auto row = [](const char* name, double value) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(name);
            ImGui::TableNextColumn();
            ImGui::Text("%.6g J", value);
        };
        row("kinetic", en.kinetic);
        row("potential", en.potential);
        row("lost in bounces", en.dissipated_bounce);
        row("lost to friction", en.dissipated_friction);
        row("lost to drag", en.dissipated_drag);
        if (spin_matters(m)) {
            row("spin kinetic", en.spin);
            row("lost to rolling", en.dissipated_rolling);
        }
        row("work by wind", en.wind_work);
        row("initial", en.initial);
        row("residual (integrator)", en.residual());
        ImGui::EndTable();
    }
    for (const Warning& w : sim.warnings())
        if (w.particle == i)
            ImGui::TextColored({1.0f, 0.75f, 0.3f, 1.0f}, "t = %.3f s: %s", w.t,
                               warning_message(w, sim.model()).c_str());
}

}  // namespace pl::ui
