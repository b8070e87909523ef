#include "physics/model/schema/integrator_fields.hpp"
#include "ui/frame_recorder.hpp"
#include "ui/launch_angles.hpp"
#include "ui/panel_state.hpp"
#include "ui/scene_editor.hpp"
#include "ui/sections.hpp"

#include <imgui.h>

#include <cmath>

namespace pl::ui {
namespace {

void velocity_to_launch(const Vec3& v, PanelState& p) {
    const LaunchPolar polar = launch_polar(v);
    p.launch_speed = polar.speed_mps;
    p.launch_elevation_deg = polar.speed_mps > 0.0 ? polar.elevation_deg : 45.0;  // a throw, once a speed is set
    p.launch_azimuth_deg = polar.azimuth_deg;
}

Vec3 launch_to_velocity(const PanelState& p) {
    return launch_velocity({p.launch_speed, p.launch_elevation_deg, p.launch_azimuth_deg});
}

}  // namespace

void draw_time_section(LabSession& s) {
    const double t = s.experiment ? s.experiment->time() : 0.0;
    ImGui::Text("t = %.4f s", t);
    ImGui::SameLine();
    ImGui::TextDisabled(s.paused ? "(paused)" : "(running)");
    if (ImGui::Button(s.paused ? "Play" : "Pause", ImVec2(60, 0))) s.paused = !s.paused;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Space");
    ImGui::SameLine();
    if (ImGui::Button("Step")) s.requests.single_step = true;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("N: one step of the smallest dt (pauses)");
    ImGui::SameLine();
    if (ImGui::Button("Next event")) s.requests.run_to_next_event = true;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Run until a bounce or rest, then pause");
    ImGui::SameLine();
    if (ImGui::Button("Reset")) s.requests.reset = true;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("R: back to the preset's initial state");

    // Log slider over 0.01 .. 10: slow motion to fast forward.
    float scale = static_cast<float>(s.time_scale);
    if (ImGui::SliderFloat("time scale", &scale, 0.01f, 10.0f, "%.3gx", ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp))
        s.time_scale = scale;
    ImGui::SameLine();
    if (ImGui::SmallButton("1x")) s.time_scale = 1.0;

    SceneEditor ed(s);
    // The scene's fixed step (variants may override it); changing it restarts the run.
    const ImVec2 dt_field = ImGui::GetCursorScreenPos();  // for the GUI tests (the help mark follows it)
    edit_field<IntegratorSettings>(ed, schema::integrator_rows[schema::row_index<IntegratorSettings>("dt")],
                                   [](Scene& sc) -> IntegratorSettings& { return sc.integrator; });
    s.widget_rects["time.dt"] = {dt_field.x, dt_field.y, ImGui::CalcItemWidth(), ImGui::GetFrameHeight()};
}

void draw_launch_section(LabSession& s) {
    PanelState& p = panels_of(s);
    if (p.launch_from_velocity) {
        velocity_to_launch(s.launch_velocity, p);
        p.launch_from_velocity = false;
    }
    bool changed = false;
    static const double speed_lo = 0.0;
    changed |= ImGui::SliderScalar("speed (m/s)", ImGuiDataType_Double, &p.launch_speed, &speed_lo, &max_launch_speed_mps, "%.3g", ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp);
    static const double el_lo = -90.0, el_hi = 90.0, az_lo = -180.0, az_hi = 180.0;
    changed |= ImGui::SliderScalar("elevation (°)", ImGuiDataType_Double, &p.launch_elevation_deg, &el_lo, &el_hi, "%.1f",
                                   ImGuiSliderFlags_AlwaysClamp);
    changed |= ImGui::SliderScalar("azimuth (°)", ImGuiDataType_Double, &p.launch_azimuth_deg, &az_lo, &az_hi, "%.1f",
                                   ImGuiSliderFlags_AlwaysClamp);
    if (changed) s.launch_velocity = launch_to_velocity(p);
    ImGui::TextDisabled("v = (%.3g, %.3g, %.3g) m/s", s.launch_velocity.x, s.launch_velocity.y, s.launch_velocity.z);
    if (ImGui::Button("Launch particle 0")) s.requests.relaunch = true;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("L: particle 0 of every variant restarts from its preset position");
    ImGui::SameLine();
    const bool has_particle = s.experiment && s.experiment->variant_count() > 0 &&
                              s.selected_particle >= 0 &&
                              static_cast<std::size_t>(s.selected_particle) < s.experiment->run(0).particle_count();
    ImGui::BeginDisabled(!has_particle);
    if (ImGui::Button("Kick selected")) {
        kick_particle(s, static_cast<std::size_t>(s.selected_particle), s.launch_velocity);
        s.status_message = "Kicked particle " + std::to_string(s.selected_particle) + " where it is";
    }
    ImGui::EndDisabled();
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip("Give the selected particle this velocity where it is now (every variant)");
}

}  // namespace pl::ui
