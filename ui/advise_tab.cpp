// Advise tab: which force terms this scene needs (physics/studies/advisor.hpp), run in the background.
#include "physics/studies/advisor.hpp"
#include "ui/panel_state.hpp"
#include "ui/sections.hpp"

#include <imgui.h>

#include <algorithm>

namespace pl::ui {
namespace {

void start_advice(LabSession& s, PanelState& p) {
    const Scene scene = s.scene;
    const double tolerance = p.advice_tolerance_m;
    p.advice_experiment = s.experiment.get();
    p.advice.start([scene, tolerance](const std::function<void(double)>& progress, const std::atomic<bool>& cancel) {
        AdviceOptions o;
        o.tolerance_m = tolerance;
        o.progress = progress;
        o.cancel = &cancel;
        return advise(scene, o);
    });
}

void variant_advice(const VariantAdvice& a) {
    ImGui::Text("drag %s, wind %s:  Re %.3g .. %.3g,  drag/weight up to %.3g,  Mach up to %.3g", to_string(a.configured),
                to_string(a.wind), a.re_min, a.re_max, a.max_drag_to_weight, a.max_mach);
    ImGui::Text("cheapest adequate drag model: %s", to_string(a.cheapest_adequate));
    for (const std::string& v : a.verdicts) ImGui::BulletText("%s", v.c_str());
    for (const std::string& w : a.warnings) ImGui::TextColored({1.0f, 0.75f, 0.3f, 1.0f}, "warning: %s", w.c_str());
    const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_Borders | ImGuiTableFlags_SizingFixedFit;
    if (!ImGui::BeginTable("runs", 4, flags)) return;
    ImGui::TableSetupColumn("drag model");
    ImGui::TableSetupColumn("wind");
    ImGui::TableSetupColumn("landing moves by (m)");
    ImGui::TableSetupColumn("apex moves by (m)");
    ImGui::TableHeadersRow();
    for (const ModelRun& r : a.runs) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(to_string(r.model));
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(r.with_wind ? "as set" : "off");
        ImGui::TableNextColumn();
        ImGui::Text("%.3g", r.landing_difference_m);
        ImGui::TableNextColumn();
        ImGui::Text("%.3g", r.apex_difference_m);
    }
    ImGui::EndTable();
}

}  // namespace

void draw_advise_tab(LabSession& s) {
    PanelState& p = panels_of(s);
    p.advice.poll();
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 5.0f);
    ImGui::InputDouble("tolerance (m)", &p.advice_tolerance_m, 0.0, 0.0, "%.3g");
    p.advice_tolerance_m = std::clamp(p.advice_tolerance_m, 1e-9, 1e3);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("A term matters when it moves the landing point or the apex by more than this");
    ImGui::SameLine();
    if (p.advice.running()) {
        ImGui::ProgressBar(static_cast<float>(p.advice.progress()), ImVec2(ImGui::GetFontSize() * 8.0f, 0));
        ImGui::SameLine();
        if (ImGui::Button("Cancel##adv")) p.advice.cancel();
    } else if (ImGui::Button("Advise")) {
        start_advice(s, p);
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Runs the scene's own trajectories with every drag model (and without wind) and reports\n"
                          "which terms change the result by more than the tolerance, like `particle-lab advise`.");
    if (!p.advice.error().empty()) ImGui::TextColored({1, 0.4f, 0.4f, 1}, "%s", p.advice.error().c_str());
    if (!p.advice.result()) {
        ImGui::TextDisabled("Ask which force terms this scene needs, measured on its own trajectories.");
        return;
    }
    const Advice& a = *p.advice.result();
    ImGui::SameLine();
    ImGui::TextDisabled("%sat %.3g m, %zu of %zu particles%s", a.cancelled ? "CANCELLED, " : "", a.tolerance_m, a.particles_used,
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
