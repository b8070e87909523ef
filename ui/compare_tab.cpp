// Compare tab: the metrics of every variant, live (physics/studies/metrics.hpp trackers fed by the
// recorder) and from a timed background run (run_comparison, which also measures the cost).
#include "physics/studies/metrics.hpp"
#include "ui/frame_recorder.hpp"
#include "ui/palette.hpp"
#include "ui/panel_state.hpp"
#include "ui/sections.hpp"

#include <imgui.h>

#include <cmath>
#include <optional>
#include <string>

namespace pl::ui {
namespace {

std::string number(double v, const char* format = "%.4g") {
    char buf[64];
    std::snprintf(buf, sizeof buf, format, v);
    return buf;
}

std::string optional_number(const std::optional<double>& v, const char* format = "%.4g") {
    return v ? number(*v, format) : std::string("-");
}

std::string signed_number(double v) { return number(v, "%+.3g"); }
std::string optional_signed(const std::optional<double>& v) { return v ? signed_number(*v) : std::string("-"); }

struct Column {
    const char* name;
    const char* tip;
};

constexpr Column columns[] = {
    {"variant", nullptr},
    {"first impact (s)", "Time of flight: the first bounce or rest on any wall"},
    {"apex (m)", "Highest centre height above the floor"},
    {"range (m)", "Horizontal distance from the start to the first impact"},
    {"bounces", "Rebounds so far (the impact that ends in rest is not one)"},
    {"at rest (s)", "When the particle came to a standstill (it is at rest now)"},
    {"drag loss (J)", "Energy dissipated by drag, all particles"},
    {"bounce loss (J)", "Energy dissipated in bounces, all particles"},
    {"friction loss (J)", "Energy dissipated by wall friction, all particles"},
    {"cost", nullptr},
};

void header_row(const char* cost_name, const char* cost_tip) {
    ImGui::TableSetupScrollFreeze(1, 1);
    for (std::size_t i = 0; i < std::size(columns); ++i) ImGui::TableSetupColumn(i == 9 ? cost_name : columns[i].name);
    ImGui::TableNextRow(ImGuiTableRowFlags_Headers);
    for (int i = 0; i < static_cast<int>(std::size(columns)); ++i) {
        ImGui::TableSetColumnIndex(i);
        ImGui::TableHeader(ImGui::TableGetColumnName(i));
        const char* tip = i == 9 ? cost_tip : columns[i].tip;
        if (tip && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tip);
    }
}

void cell(const std::string& text) {
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(text.c_str());
}

// One table row per variant: values, or differences to the baseline.
void metrics_table(const char* id, LabSession& s, const std::vector<VariantMetrics>& rows, std::size_t particle,
                   bool differences, const std::vector<double>& cost, const char* cost_name, const char* cost_tip) {
    const PanelState& p = panels_of(s);
    const std::size_t baseline = static_cast<std::size_t>(std::max(0, p.baseline_variant)) < rows.size()
                                     ? static_cast<std::size_t>(p.baseline_variant)
                                     : 0;
    const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_Borders | ImGuiTableFlags_SizingFixedFit |
                                  ImGuiTableFlags_ScrollX | ImGuiTableFlags_ScrollY;
    if (!ImGui::BeginTable(id, static_cast<int>(std::size(columns)), flags, ImVec2(0, ImGui::GetContentRegionAvail().y)))
        return;
    header_row(cost_name, cost_tip);
    for (std::size_t v = 0; v < rows.size(); ++v) {
        const VariantMetrics& m = rows[v];
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        const Rgba c = series_color(rows.size() > 1 ? static_cast<int>(v) : static_cast<int>(particle));
        ImGui::ColorButton("##c", ImVec4(c[0], c[1], c[2], 1.0f), ImGuiColorEditFlags_NoTooltip, ImVec2(10, 10));
        ImGui::SameLine();
        const std::string name = variant_name(s, v) + (v == baseline && rows.size() > 1 ? " (baseline)" : "");
        ImGui::TextUnformatted(name.c_str());
        if (particle >= m.particles.size()) continue;
        const ParticleMetrics& pm = m.particles[particle];
        if (differences && v != baseline) {
            const MetricsDifference d = metrics_difference(m, rows[baseline], particle);
            cell(optional_signed(d.first_impact_time));
            cell(signed_number(d.apex_height));
            cell(optional_signed(d.range_at_first_impact));
            cell(number(static_cast<double>(d.bounces), "%+.0f"));
            cell(optional_signed(d.time_to_rest));
            cell(signed_number(d.lost_drag));
            cell(signed_number(d.lost_bounce));
            cell(signed_number(d.lost_friction));
            cell(v < cost.size() && baseline < cost.size() ? signed_number(cost[v] - cost[baseline]) : "-");
        } else {
            cell(optional_number(pm.first_impact_time));
            cell(number(pm.apex_height));
            cell(optional_number(pm.range_at_first_impact));
            cell(std::to_string(pm.bounces));
            cell(optional_number(pm.time_to_rest));
            cell(number(m.lost_drag));
            cell(number(m.lost_bounce));
            cell(number(m.lost_friction));
            cell(v < cost.size() ? number(cost[v]) : "-");
        }
    }
    ImGui::EndTable();
}

void timed_run_controls(LabSession& s, PanelState& p) {
    p.timed_compare.poll();
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 5.0f);
    ImGui::InputDouble("duration (s)##timed", &p.timed_compare_duration_s, 0.0, 0.0, "%.3g");
    p.timed_compare_duration_s = std::clamp(p.timed_compare_duration_s, 1e-3, 1e4);
    ImGui::SameLine();
    if (p.timed_compare.running()) {
        ImGui::ProgressBar(static_cast<float>(p.timed_compare.progress()), ImVec2(ImGui::GetFontSize() * 10.0f, 0));
        ImGui::SameLine();
        if (ImGui::Button("Cancel##timed")) p.timed_compare.cancel();
    } else if (ImGui::Button("Timed run")) {
        const Scene scene = s.scene;
        const double duration = p.timed_compare_duration_s;
        p.timed_compare.start([scene, duration](const std::function<void(double)>& progress, const std::atomic<bool>& cancel) {
            CompareOptions o;
            o.duration_s = duration;
            o.progress = progress;
            o.cancel = &cancel;
            return run_comparison(scene, o);
        });
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Runs every variant from the start to this time in the background and measures its cost\n"
                          "(physics wall time per simulated second), like `particle-lab compare`.");
}

}  // namespace

void draw_compare_tab(LabSession& s) {
    PanelState& p = panels_of(s);
    PlotHistory& h = history_of(s);
    const std::size_t variants = s.experiment->variant_count();
    const std::size_t particles = s.experiment->run(0).particle_count();
    const std::size_t particle =
        s.selected_particle >= 0 && static_cast<std::size_t>(s.selected_particle) < particles ? static_cast<std::size_t>(s.selected_particle) : 0;

    int& mode = p.compare_mode;
    ImGui::RadioButton("live", &mode, 0);
    ImGui::SameLine();
    ImGui::RadioButton("timed run", &mode, 1);
    ImGui::SameLine();
    ImGui::TextDisabled("| particle %zu |", particle);
    bool& differences = p.compare_differences;
    if (variants > 1) {
        ImGui::SameLine();
        ImGui::SetNextItemWidth(ImGui::GetFontSize() * 9.0f);
        if (p.baseline_variant < 0 || static_cast<std::size_t>(p.baseline_variant) >= variants) p.baseline_variant = 0;
        if (ImGui::BeginCombo("baseline", variant_name(s, static_cast<std::size_t>(p.baseline_variant)).c_str())) {
            for (std::size_t v = 0; v < variants; ++v)
                if (ImGui::Selectable(variant_name(s, v).c_str(), static_cast<int>(v) == p.baseline_variant))
                    p.baseline_variant = static_cast<int>(v);
            ImGui::EndCombo();
        }
        ImGui::SameLine();
        ImGui::Checkbox("differences", &differences);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("Show each variant minus the baseline");
    }

    if (mode == 0) {
        if (h.trackers.size() != variants) {
            ImGui::TextWrapped("Live metrics follow every step of up to %zu particles; this scene has %zu. "
                               "Use the timed run instead.", PlotHistory::max_metrics_particles, particles);
            return;
        }
        std::vector<VariantMetrics> rows;
        std::vector<double> cost;
        for (std::size_t v = 0; v < variants; ++v) {
            const Simulation& sim = s.experiment->run(v);
            rows.push_back(metrics_of(h.trackers[v], sim));
            cost.push_back(sim.time() > 0.0 ? static_cast<double>(sim.counters().gravity) / sim.time() : 0.0);
        }
        metrics_table("##live", s, rows, particle, differences, cost, "force evals / s",
                      "Force evaluations (one per particle per evaluation) per simulated second: the work the\n"
                      "method does. Wall-clock cost: use the timed run.");
        return;
    }
    timed_run_controls(s, p);
    if (!p.timed_compare.error().empty()) ImGui::TextColored({1, 0.4f, 0.4f, 1}, "%s", p.timed_compare.error().c_str());
    if (!p.timed_compare.result()) {
        ImGui::TextDisabled("No timed run yet.");
        return;
    }
    const Comparison& c = *p.timed_compare.result();
    if (!c.error.empty()) {
        ImGui::TextColored({1, 0.4f, 0.4f, 1}, "duration: %s", c.error.c_str());
        return;
    }
    ImGui::SameLine();
    ImGui::TextDisabled("%s%g s simulated", c.cancelled ? "cancelled, " : "", c.variants.empty() ? 0.0 : c.variants[0].simulated_seconds);
    std::vector<double> cost;
    for (const VariantMetrics& m : c.variants) cost.push_back(1e3 * m.cost());
    if (c.variants.size() != variants) {
        ImGui::TextDisabled("(the scene changed since this run)");
        return;
    }
    metrics_table("##timed", s, c.variants, particle, differences, cost, "cost (ms / sim s)",
                  "Physics wall time per simulated second, measured in the background run.");
}

}  // namespace pl::ui
