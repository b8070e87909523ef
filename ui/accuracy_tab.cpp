// Accuracy tab: the work-precision study (physics/studies/accuracy_study.hpp) of the selected particle
// and variant, run in the background; error against cost on log-log axes, one line per method,
// the current setting marked.
#include "physics/studies/accuracy_study.hpp"
#include "ui/palette.hpp"
#include "ui/panel_state.hpp"
#include "ui/plot.hpp"
#include "ui/sections.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

namespace pl::ui {
namespace {

int method_index(Method m) { return static_cast<int>(m); }

double cost_of(const AccuracyRow& r, int axis) {
    return axis == 0 ? static_cast<double>(r.force_evaluations) : r.wall_seconds_per_sim_second;
}

double error_of(const AccuracyRow& r, int axis) {
    if (axis == 0) return r.position_error;
    if (axis == 1) return r.velocity_error;
    return r.bounce_time_error.value_or(std::nan(""));
}

bool is_current(const AccuracyRow& r, const IntegratorSettings& g) {
    if (r.method != g.method) return false;
    if (r.adaptive) return g.method == Method::dopri5 && g.adaptive && std::abs(r.tolerance - g.rtol) <= 1e-12 * g.rtol;
    const bool current_adaptive = g.method == Method::dopri5 && g.adaptive;
    return !current_adaptive && std::abs(r.dt - g.dt) <= 1e-9 * g.dt;
}

void start_study(LabSession& s, PanelState& p) {
    const Scene scene = s.scene;
    AccuracyOptions o;
    o.duration_s = p.accuracy_duration_s;
    o.variant = static_cast<std::size_t>(std::max(0, s.selected_variant));
    o.particle = static_cast<std::size_t>(std::max(0, s.selected_particle));
    p.accuracy_experiment = s.experiment.get();
    p.accuracy.start([scene, o](const std::function<void(double)>& progress, const std::atomic<bool>& cancel) {
        AccuracyOptions options = o;
        options.progress = progress;
        options.cancel = &cancel;
        return run_accuracy_study(scene, options);
    });
}

void controls(LabSession& s, PanelState& p) {
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 4.5f);
    ImGui::InputDouble("duration (s)##acc", &p.accuracy_duration_s, 0.0, 0.0, "%.3g");
    p.accuracy_duration_s = std::clamp(p.accuracy_duration_s, 1e-3, 100.0);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 9.0f);
    ImGui::Combo("cost##acc", &p.accuracy_cost_axis, "force evaluations\0wall time / sim s\0");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 9.0f);
    ImGui::Combo("error##acc", &p.accuracy_error_axis, "position (m)\0velocity (m/s)\0bounce time (s)\0");
    ImGui::SameLine();
    if (p.accuracy.running()) {
        ImGui::ProgressBar(static_cast<float>(p.accuracy.progress()), ImVec2(ImGui::GetFontSize() * 8.0f, 0));
        ImGui::SameLine();
        if (ImGui::Button("Cancel##acc")) p.accuracy.cancel();
    } else if (ImGui::Button("Run study")) {
        start_study(s, p);
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Runs particle %d of %s with every method over a ladder of dt (tolerances for adaptive\n"
                          "dopri5) and compares each with a reference solution. Runs in the background.",
                          s.selected_particle, variant_name(s, static_cast<std::size_t>(std::max(0, s.selected_variant))).c_str());
}

void diagram(const AccuracyReport& r, const PanelState& p, const IntegratorSettings& current, float width) {
    static const char* cost_labels[] = {"force evaluations", "wall time per simulated second (s)"};
    static const char* error_labels[] = {"position error at the end (m)", "velocity error at the end (m/s)",
                                         "bounce time error (s)"};
    // Built completely before plotting: the plot keeps the pointers until EndPlot.
    struct Curve {
        std::string label;
        std::vector<double> xs, ys;
        Rgba color;
    };
    std::map<std::pair<int, bool>, std::vector<const AccuracyRow*>> groups;
    for (const AccuracyRow& row : r.rows) groups[{method_index(row.method), row.adaptive}].push_back(&row);
    std::vector<Curve> curves;
    for (auto& [key, rows] : groups) {
        std::sort(rows.begin(), rows.end(), [&](const AccuracyRow* a, const AccuracyRow* b) {
            return cost_of(*a, p.accuracy_cost_axis) < cost_of(*b, p.accuracy_cost_axis);
        });
        std::string label = std::string(to_string(static_cast<Method>(key.first))) + (key.second ? " (tol)" : "");
        for (const MethodOrder& o : r.orders) {
            if (key.second || o.method != static_cast<Method>(key.first)) continue;
            char order[48];
            if (o.observed) std::snprintf(order, sizeof order, "  order %.2f", *o.observed);
            else std::snprintf(order, sizeof order, "  order: too few points above the floor");
            label += order;
        }
        Curve c{label, {}, {}, series_color(key.first)};
        for (const AccuracyRow* row : rows) {
            c.xs.push_back(cost_of(*row, p.accuracy_cost_axis));
            c.ys.push_back(error_of(*row, p.accuracy_error_axis));
        }
        curves.push_back(std::move(c));
    }
    std::vector<double> current_x, current_y;
    for (const AccuracyRow& row : r.rows) {
        if (!is_current(row, current)) continue;
        current_x.push_back(cost_of(row, p.accuracy_cost_axis));
        current_y.push_back(error_of(row, p.accuracy_error_axis));
    }
    if (!plot::BeginPlot("##work_precision", ImVec2(width, -1), plot::PlotFlags_LogLog | plot::PlotFlags_LegendOutside)) return;
    plot::SetupAxes(cost_labels[p.accuracy_cost_axis], error_labels[p.accuracy_error_axis]);
    for (const Curve& c : curves) {
        const int n = static_cast<int>(c.xs.size());
        plot::PlotLine(c.label.c_str(), c.xs.data(), c.ys.data(), n, c.color, 1.5f);
        plot::PlotMarkers(c.label.c_str(), c.xs.data(), c.ys.data(), n, c.color, plot::Marker::circle, 3.0f);
    }
    const Rgba white{1.0f, 1.0f, 1.0f, 1.0f};
    plot::PlotMarkers("##current", current_x.data(), current_y.data(), static_cast<int>(current_x.size()), white,
                      plot::Marker::diamond, 6.0f);
    if (!current_x.empty()) plot::PlotText("current setting", current_x[0], current_y[0], white);
    plot::EndPlot();
}

void table(const AccuracyReport& r, const IntegratorSettings& current) {
    const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_Borders | ImGuiTableFlags_ScrollY |
                                  ImGuiTableFlags_ScrollX | ImGuiTableFlags_SizingFixedFit;
    if (!ImGui::BeginTable("##accuracy_rows", 7, flags, ImVec2(0, ImGui::GetContentRegionAvail().y))) return;
    ImGui::TableSetupScrollFreeze(1, 1);
    for (const char* name : {"method", "dt / tol", "steps", "force evals", "wall s / sim s", "position err (m)", "bounce t err (s)"})
        ImGui::TableSetupColumn(name);
    ImGui::TableHeadersRow();
    for (const AccuracyRow& row : r.rows) {
        ImGui::TableNextRow();
        if (is_current(row, current)) ImGui::TableSetBgColor(ImGuiTableBgTarget_RowBg1, IM_COL32(90, 90, 40, 160));
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(to_string(row.method));
        ImGui::TableNextColumn();
        if (row.adaptive) ImGui::Text("tol %.0e", row.tolerance);
        else ImGui::Text("%.3g s", row.dt);
        ImGui::TableNextColumn();
        ImGui::Text("%llu", static_cast<unsigned long long>(row.steps));
        ImGui::TableNextColumn();
        ImGui::Text("%llu", static_cast<unsigned long long>(row.force_evaluations));
        ImGui::TableNextColumn();
        ImGui::Text("%.2e", row.wall_seconds_per_sim_second);
        ImGui::TableNextColumn();
        ImGui::Text("%.2e", row.position_error);
        ImGui::TableNextColumn();
        if (row.bounce_time_error) ImGui::Text("%.2e", *row.bounce_time_error);
        else ImGui::TextUnformatted("-");
    }
    ImGui::EndTable();
}

}  // namespace

void draw_accuracy_tab(LabSession& s) {
    PanelState& p = panels_of(s);
    p.accuracy.poll();
    controls(s, p);
    if (!p.accuracy.error().empty()) ImGui::TextColored({1, 0.4f, 0.4f, 1}, "%s", p.accuracy.error().c_str());
    if (!p.accuracy.result()) {
        ImGui::TextDisabled("Run the study to see each method's error against its cost on this scene.");
        return;
    }
    const AccuracyReport& r = *p.accuracy.result();
    if (!r.error.empty()) {
        ImGui::TextColored({1, 0.4f, 0.4f, 1}, "%s", r.error.c_str());
        return;
    }
    const std::size_t v = std::min<std::size_t>(static_cast<std::size_t>(std::max(0, s.selected_variant)),
                                                s.experiment->variant_count() - 1);
    const IntegratorSettings& current = s.experiment->run(v).model().integrator;
    ImGui::SameLine();
    ImGui::TextDisabled("%s%s%s", r.cancelled ? "cancelled " : "", "(?)",
                        p.accuracy_experiment != s.experiment.get() ? "  scene changed: run again" : "");
    if (ImGui::IsItemHovered()) {
        std::string orders;
        for (const MethodOrder& o : r.orders) {
            char buf[192];
            if (o.observed) std::snprintf(buf, sizeof buf, "\n  %s: %.2f (expected %d)", to_string(o.method), *o.observed, o.expected);
            else std::snprintf(buf, sizeof buf, "\n  %s: - (expected %d): %s", to_string(o.method), o.expected,
                               o.note().c_str());
            orders += buf;
        }
        ImGui::SetTooltip("%s, particle %zu, errors at t = %.4g s\nreference: %s\nobserved order of the fixed-step methods "
                          "(log-log slope of error vs dt,\nover the errors at least %g x their floor: the reference's error %.3g m + round-off):%s",
                          r.variant_label.empty() ? "scene" : r.variant_label.c_str(), r.particle, r.duration_s,
                          r.reference.c_str(), order_floor_margin, r.reference_error, orders.c_str());
    }
    ImGui::SameLine();
    ImGui::RadioButton("diagram##acc", &p.accuracy_view, 0);
    ImGui::SameLine();
    ImGui::RadioButton("table##acc", &p.accuracy_view, 1);
    ImGui::SameLine();
    ImGui::Checkbox("own window##acc", &p.accuracy_window);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Show the diagram in a window of its own (movable, resizable)");
    if (p.accuracy_view == 0) diagram(r, p, current, -1.0f);
    else table(r, current);
    if (!p.accuracy_window) return;
    ImGui::SetNextWindowSize(ImVec2(760, 480), ImGuiCond_FirstUseEver);
    if (ImGui::Begin("Work-precision diagram", &p.accuracy_window)) diagram(r, p, current, -1.0f);
    ImGui::End();
}

}  // namespace pl::ui
