// Compare tab: the metrics of every variant, live (physics/studies/metrics.hpp trackers fed by the
// recorder) and from a timed background run (run_comparison, which also measures the cost).
#include "physics/studies/metrics.hpp"
#include "ui/frame_recorder.hpp"
#include "ui/palette.hpp"
#include "ui/panel_state.hpp"
#include "ui/pinned_runs.hpp"
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

// The rows of the live table: every variant, then the pinned runs.
struct RowSet {
    std::vector<VariantMetrics> metrics;
    std::vector<std::string> names;
    std::vector<Rgba> colors;
    std::vector<double> cost;  // per row; pinned runs have none (NaN)
};

std::size_t baseline_row(const PanelState& p, std::size_t rows) {
    return static_cast<std::size_t>(std::max(0, p.baseline_variant)) < rows ? static_cast<std::size_t>(p.baseline_variant) : 0;
}

std::string cost_cell(const std::vector<double>& cost, std::size_t row, std::size_t baseline, bool difference) {
    if (row >= cost.size() || std::isnan(cost[row])) return "-";
    if (!difference) return number(cost[row]);
    return baseline < cost.size() && !std::isnan(cost[baseline]) ? signed_number(cost[row] - cost[baseline]) : "-";
}

// One table row per variant (and pinned run): values, or differences to the baseline.
void metrics_table(const char* id, LabSession& s, const RowSet& set, std::size_t particle, bool differences,
                   const char* cost_name, const char* cost_tip) {
    const std::vector<VariantMetrics>& rows = set.metrics;
    const std::size_t baseline = baseline_row(panels_of(s), rows.size());
    const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_Borders | ImGuiTableFlags_SizingFixedFit |
                                  ImGuiTableFlags_ScrollX | ImGuiTableFlags_ScrollY;
    if (!ImGui::BeginTable(id, static_cast<int>(std::size(columns)), flags, ImVec2(0, ImGui::GetContentRegionAvail().y)))
        return;
    header_row(cost_name, cost_tip);
    for (std::size_t v = 0; v < rows.size(); ++v) {
        const VariantMetrics& m = rows[v];
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        const Rgba c = set.colors[v];
        ImGui::ColorButton("##c", ImVec4(c[0], c[1], c[2], 1.0f), ImGuiColorEditFlags_NoTooltip, ImVec2(10, 10));
        ImGui::SameLine();
        const std::string name = set.names[v] + (v == baseline && rows.size() > 1 ? " (baseline)" : "");
        ImGui::TextUnformatted(name.c_str());
        if (particle >= m.particles.size()) continue;
        const ParticleMetrics& pm = m.particles[particle];
        if (differences && v != baseline && particle < rows[baseline].particles.size()) {
            const MetricsDifference d = metrics_difference(m, rows[baseline], particle);
            cell(optional_signed(d.first_impact_time));
            cell(signed_number(d.apex_height));
            cell(optional_signed(d.range_at_first_impact));
            cell(number(static_cast<double>(d.bounces), "%+.0f"));
            cell(optional_signed(d.time_to_rest));
            cell(signed_number(d.lost_drag));
            cell(signed_number(d.lost_bounce));
            cell(signed_number(d.lost_friction));
            cell(cost_cell(set.cost, v, baseline, true));
        } else {
            cell(optional_number(pm.first_impact_time));
            cell(number(pm.apex_height));
            cell(optional_number(pm.range_at_first_impact));
            cell(std::to_string(pm.bounces));
            cell(optional_number(pm.time_to_rest));
            cell(number(m.lost_drag));
            cell(number(m.lost_bounce));
            cell(number(m.lost_friction));
            cell(cost_cell(set.cost, v, baseline, false));
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

Rgba row_color(std::size_t variants, std::size_t v, std::size_t particle) {
    return series_color(variants > 1 ? static_cast<int>(v) : static_cast<int>(particle));
}

RowSet live_rows(const LabSession& s, const PlotHistory& h, std::size_t particle) {
    RowSet set;
    const std::size_t variants = s.experiment->variant_count();
    for (std::size_t v = 0; v < variants; ++v) {
        const Simulation& sim = s.experiment->run(v);
        set.metrics.push_back(metrics_of(h.trackers[v], sim));
        set.names.push_back(variant_name(s, v));
        set.colors.push_back(row_color(variants, v, particle));
        set.cost.push_back(sim.time() > 0.0 ? static_cast<double>(sim.counters().gravity) / sim.time() : 0.0);
    }
    if (const PinBoard* board = pins_if_any(s))
        for (const PinnedRun& run : board->runs) {
            if (!run.metrics) continue;
            set.metrics.push_back(*run.metrics);
            set.names.push_back(run.label);
            set.colors.push_back(pin_color(run.number, 1.0f));
            set.cost.push_back(std::nan(""));
        }
    return set;
}

RowSet timed_rows(const LabSession& s, const Comparison& c, std::size_t particle) {
    RowSet set;
    for (std::size_t v = 0; v < c.variants.size(); ++v) {
        set.metrics.push_back(c.variants[v]);
        set.names.push_back(variant_name(s, v));
        set.colors.push_back(row_color(c.variants.size(), v, particle));
        set.cost.push_back(1e3 * c.variants[v].cost());
    }
    return set;
}

void baseline_controls(PanelState& p, const RowSet& set, bool& differences) {
    ImGui::SameLine();
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 9.0f);
    const std::size_t baseline = baseline_row(p, set.names.size());
    p.baseline_variant = static_cast<int>(baseline);
    if (ImGui::BeginCombo("baseline", set.names[baseline].c_str())) {
        for (std::size_t v = 0; v < set.names.size(); ++v)
            if (ImGui::Selectable(set.names[v].c_str(), v == baseline)) p.baseline_variant = static_cast<int>(v);
        ImGui::EndCombo();
    }
    ImGui::SameLine();
    ImGui::Checkbox("differences", &differences);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Show each row minus the baseline (variants and pinned runs)");
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
    const bool live = mode == 0;
    RowSet set;
    if (live && h.trackers.size() == variants) set = live_rows(s, h, particle);
    if (!live && p.timed_compare.result() && p.timed_compare.result()->variants.size() == variants)
        set = timed_rows(s, *p.timed_compare.result(), particle);
    if (set.metrics.size() > 1) baseline_controls(p, set, differences);

    if (live) {
        if (h.trackers.size() != variants) {
            ImGui::TextWrapped("Live metrics follow every step of up to %zu particles; this scene has %zu. "
                               "Use the timed run instead.", PlotHistory::max_metrics_particles, particles);
            return;
        }
        metrics_table("##live", s, set, particle, differences, "force evals / s",
                      "Force evaluations (one per particle per evaluation) per simulated second: the work the\n"
                      "method does. Wall-clock cost: use the timed run. Pinned runs: their metrics when pinned.");
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
    if (c.variants.size() != variants) {
        ImGui::TextDisabled("(the scene changed since this run)");
        return;
    }
    metrics_table("##timed", s, set, particle, differences, "cost (ms / sim s)",
                  "Physics wall time per simulated second, measured in the background run.");
}

}  // namespace pl::ui
