#include "app/particle_tooltip.hpp"

#include "physics/stepping/energy.hpp"
#include "ui/palette.hpp"

#include <glm/geometric.hpp>
#include <imgui.h>

#include <cstdio>
#include <string>

namespace pl::app {

namespace {

std::string resting_description(std::uint8_t walls) {
    if (walls == 0) return "in flight";
    std::string text = "resting on";
    for (int w = 0; w < wall_count; ++w)
        if (walls & (1u << w)) text += std::string(" ") + (w == Wall::y_min ? "the floor" : wall_name(w));
    return text;
}

void row(const char* name, const char* value) {
    ImGui::TextDisabled("%s", name);
    ImGui::SameLine(ImGui::GetFontSize() * 5.5f);
    ImGui::TextUnformatted(value);
}

}  // namespace

void show_particle_tooltip(const ui::LabSession& session, const ParticleRef& p) {
    const Experiment& e = *session.experiment;
    const Simulation& run = e.run(p.variant);
    const ParticleState& s = run.state();
    const std::size_t i = p.particle;
    const Vec3 x = s.position(i), v = s.velocity(i);
    const Room& room = run.model().room;
    const EnergyBreakdown energy = particle_energy(s, i, run.model().world.gravity, room);
    const ui::Rgb c = ui::series_color(e.variant_count(), p.variant, i);
    char buf[128];
    ImGui::BeginTooltip();
    ImGui::ColorButton("##colour", ImVec4(c.r, c.g, c.b, 1.0f), ImGuiColorEditFlags_NoTooltip, ImVec2(12, 12));
    ImGui::SameLine();
    // The variant's name matters only when there are several.
    const std::string label = e.variant_count() > 1 ? run.model().label : std::string();
    ImGui::Text("Particle %zu%s%s", i, label.empty() ? "" : "  -  ", label.c_str());
    ImGui::Separator();
    std::snprintf(buf, sizeof buf, "(%.3f, %.3f, %.3f) m", x.x, x.y, x.z);
    row("position", buf);
    std::snprintf(buf, sizeof buf, "(%.3f, %.3f, %.3f) m/s", v.x, v.y, v.z);
    row("velocity", buf);
    std::snprintf(buf, sizeof buf, "%.4g m/s", glm::length(v));
    row("speed", buf);
    std::snprintf(buf, sizeof buf, "%.4g m above the floor", x.y - room.floor_y());
    row("height", buf);
    std::snprintf(buf, sizeof buf, "%.4g J", energy.kinetic);
    row("kinetic", buf);
    std::snprintf(buf, sizeof buf, "%.4g kg, radius %.4g m", s.mass[i], s.radius[i]);
    row("mass", buf);
    row("state", s.frozen[i] ? "frozen (state became non-finite)" : resting_description(s.resting[i]).c_str());
    ImGui::TextDisabled("click to select");
    ImGui::EndTooltip();
}

}  // namespace pl::app
