// Advise tab: which force terms this scene needs (physics/studies/advisor.hpp), run in the background.
#include "physics/studies/advisor.hpp"
#include "ui/panel_state.hpp"
#include "ui/sections.hpp"

#include <imgui.h>

#include <algorithm>
#include <string>

namespace pl::ui {
namespace {

void start_advice(LabSession& s, PanelState& p) {
    const Scene scene = s.scene;
    AdviceOptions options;
    options.tolerance_m = p.advice_tolerance_m;
    options.tolerance_s = p.advice_tolerance_s;
    options.tolerance_mps = p.advice_tolerance_mps;
    p.advice_experiment = s.experiment.get();
    p.advice.start([scene, options](const std::function<void(double)>& progress, const std::atomic<bool>& cancel) {
        AdviceOptions o = options;
        o.progress = progress;
        o.cancel = &cancel;
        return advise(scene, o);
    });
}

// The collision estimate's numbers (physics/studies/collision_estimate.hpp), over all particles.
void collision_estimate(const VariantAdvice& a) {
    const CollisionEstimate& e = a.collisions;
    if (!e.applicable) return;
    ImGui::Text("collisions %s:  %zu particles, volume fraction %.3g, mean free path %.3g m, speed %.3g m/s, "
                "%.3g collisions per particle over %.3g s, %.3g layers on the floor",
                a.collisions_recommended ? "recommended" : "not needed", e.particles, e.volume_fraction,
                e.mean_free_path_m, e.speed_m_s, e.per_particle, e.duration_s, e.layers);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Kinetic theory: mean free path 1/(sqrt 2 n sigma), sigma = pi (r_i + r_j)^2 averaged over pairs,\n"
                          "speed = rms of each particle's drag-free speed at the floor; layers = sum pi r^2 / (0.84 floor area).\n"
                          "Collisions are recommended when the balls must stack (more than one layer), when the scene\n"
                          "expects at least one collision in all, or when the on/off runs differ beyond tolerance.");
}

void variant_advice(const VariantAdvice& a) {
    const double ratio = a.density_ratio.empty() ? 0.0 : *std::max_element(a.density_ratio.begin(), a.density_ratio.end());
    ImGui::Text("drag %s, wind %s, buoyancy %s:  Re %.3g .. %.3g,  drag/weight up to %.3g,  Mach up to %.3g,  "
                "rho_air/rho_particle up to %.3g",
                to_string(a.configured), to_string(a.wind), a.buoyancy ? "on" : "off", a.re_min, a.re_max,
                a.max_drag_to_weight, a.max_mach, ratio);
    ImGui::Text("cheapest adequate drag model: %s", to_string(a.cheapest_adequate));
    collision_estimate(a);
    // Wrapped: a verdict names each metric beyond tolerance, a line too long for the panel.
    for (const std::string& v : a.verdicts) {
        ImGui::Bullet();
        ImGui::TextWrapped("%s", v.c_str());
    }
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.75f, 0.3f, 1.0f));
    for (const std::string& w : a.warnings) ImGui::TextWrapped("warning: %s", w.c_str());
    ImGui::PopStyleColor();
    // One row per term of the table (physics/studies/advisor_terms.hpp), one column per metric:
    // the difference on - off (drag models: model - sphere_re), highlighted beyond tolerance.
    const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_Borders | ImGuiTableFlags_SizingFixedFit;
    if (!ImGui::BeginTable("runs", 2 + static_cast<int>(advice_metric_count), flags)) return;
    ImGui::TableSetupColumn("term");
    ImGui::TableSetupColumn("in scene");
    for (AdviceMetric m : advice_metrics) {
        const std::string header = std::string(to_string(m)) + " (" + unit_of(m) + ")";
        ImGui::TableSetupColumn(header.c_str());
    }
    ImGui::TableHeadersRow();
    for (const ModelRun& r : a.runs) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(r.term.c_str());
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(r.in_scene ? "yes" : "no");
        for (AdviceMetric m : advice_metrics) {
            ImGui::TableNextColumn();
            const MetricDelta& d = r.metric(m);
            if (!r.not_applicable.empty()) ImGui::TextDisabled("n/a");
            else if (!d.measured) ImGui::TextDisabled("-");
            else if (d.beyond_tolerance && d.within_chaos)  // beyond tolerance, but so is a nudge of the starts
                ImGui::TextColored({0.75f, 0.65f, 0.5f, 1.0f}, "%s%+.3g~", d.at_least ? ">|" : "", d.difference);
            else if (d.beyond_tolerance)
                ImGui::TextColored({1.0f, 0.75f, 0.3f, 1.0f}, "%s%+.3g", d.at_least ? ">|" : "", d.difference);
            else ImGui::Text("%s%+.3g", d.at_least ? ">|" : "", d.difference);
            if (ImGui::IsItemHovered() && d.measured)
                ImGui::SetTooltip("%s%s", describe(m, d).c_str(),
                                  d.within_chaos ? "\nwithin the scene's chaos: moving the starts changes it as much (see the warning)" : "");
        }
    }
    ImGui::EndTable();
}

}  // namespace

void draw_advise_tab(LabSession& s) {
    PanelState& p = panels_of(s);
    p.advice.poll();
    ImGui::TextUnformatted("tolerances");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 5.0f);
    ImGui::InputDouble("m##advise_tolerance", &p.advice_tolerance_m, 0.0, 0.0, "%.3g");
    p.advice_tolerance_m = std::clamp(p.advice_tolerance_m, 1e-9, 1e3);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Tolerance of range, apex height and landing point");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 5.0f);
    ImGui::InputDouble("s##advise_tolerance", &p.advice_tolerance_s, 0.0, 0.0, "%.3g");
    p.advice_tolerance_s = std::clamp(p.advice_tolerance_s, 1e-9, 1e3);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Tolerance of landing time and time to rest");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 5.0f);
    ImGui::InputDouble("m/s##advise_tolerance", &p.advice_tolerance_mps, 0.0, 0.0, "%.3g");
    p.advice_tolerance_mps = std::clamp(p.advice_tolerance_mps, 1e-9, 1e3);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Tolerance of impact speeds. A term matters when any metric differs by more than its tolerance");
    ImGui::SameLine();
    if (p.advice.running()) {
        ImGui::ProgressBar(static_cast<float>(p.advice.progress()), ImVec2(ImGui::GetFontSize() * 8.0f, 0));
        ImGui::SameLine();
        if (ImGui::Button("Cancel##adv")) p.advice.cancel();
    } else {
        if (ImGui::Button("Advise")) start_advice(s, p);
        note_item_rect(s, "advise.run");
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Runs the scene's own trajectories with each term on and off (drag, buoyancy, added mass, ISA air,\n"
                          "collisions, wind) and each\n"
                          "drag model against sphere_re, and reports which change landing time, impact speeds, time to\n"
                          "rest, range, apex or landing point by more than the tolerances, like `particle-lab advise`.");
    if (!p.advice.error().empty()) ImGui::TextColored({1, 0.4f, 0.4f, 1}, "%s", p.advice.error().c_str());
    if (!p.advice.result()) {
        ImGui::TextDisabled("Ask which force terms this scene needs, measured on its own trajectories.");
        return;
    }
    const Advice& a = *p.advice.result();
    ImGui::SameLine();
    ImGui::TextDisabled("%sat %.3g m, %.3g s, %.3g m/s, %zu of %zu particles%s", a.cancelled ? "CANCELLED, " : "",
                        a.tolerances.metres, a.tolerances.seconds, a.tolerances.metres_per_second, a.particles_used,
                        a.particles_total, p.advice_experiment != s.experiment.get() ? "  (the scene changed since: run again)" : "");
    ImGui::BeginChild("##advice", ImVec2(0, 0));
    for (std::size_t v = 0; v < a.variants.size(); ++v) {
        ImGui::PushID(static_cast<int>(v));
        const std::string title = a.variants[v].label.empty() ? std::string("scene") : a.variants[v].label;
        if (ImGui::CollapsingHeader(title.c_str(), ImGuiTreeNodeFlags_DefaultOpen)) variant_advice(a.variants[v]);
        ImGui::PopID();
    }
    ImGui::EndChild();
}

}  // namespace pl::ui
