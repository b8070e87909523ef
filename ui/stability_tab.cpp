// Stability tab: the dt x drag-stiffness map of the current method (physics/studies/stability_study.hpp),
// computed in the background, coloured by outcome, with the theoretical limit and the current
// setting marked; beside it the collision slice (pairs thrown at each other) on the same method.
#include "physics/studies/stability_study.hpp"
#include "ui/panel_state.hpp"
#include "ui/plot.hpp"
#include "ui/sections.hpp"

#include <imgui.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace pl::ui {
namespace {

Rgba outcome_color(StabilityOutcome o) {
    switch (o) {
        case StabilityOutcome::stable: return {0.30f, 0.70f, 0.35f, 0.85f};
        case StabilityOutcome::energy_growth: return {1.00f, 0.60f, 0.15f, 0.85f};
        case StabilityOutcome::nan: return {0.90f, 0.20f, 0.20f, 0.85f};
        case StabilityOutcome::escaped: return {0.65f, 0.35f, 0.90f, 0.85f};
        case StabilityOutcome::jitter: return {0.90f, 0.85f, 0.25f, 0.85f};
        case StabilityOutcome::tunnelled: return {0.95f, 0.45f, 0.75f, 0.85f};
        case StabilityOutcome::overlap: return {0.35f, 0.75f, 0.95f, 0.85f};
    }
    return {0.5f, 0.5f, 0.5f, 1.0f};
}

// 1, 2, 5 per decade from lo to hi.
std::vector<double> one_two_five(double lo, double hi) {
    std::vector<double> out;
    for (double decade = std::pow(10.0, std::floor(std::log10(lo))); decade <= hi; decade *= 10.0)
        for (double m : {1.0, 2.0, 5.0})
            if (m * decade >= lo * (1 - 1e-12) && m * decade <= hi * (1 + 1e-12)) out.push_back(m * decade);
    return out;
}

// Cell edges half way (geometrically) between neighbouring grid values.
double lower_edge(const std::vector<double>& v, std::size_t i) {
    return i > 0 ? std::sqrt(v[i - 1] * v[i]) : v[0] / std::sqrt(v[1] / v[0]);
}
double upper_edge(const std::vector<double>& v, std::size_t i) {
    return i + 1 < v.size() ? std::sqrt(v[i] * v[i + 1]) : v[i] * std::sqrt(v[i] / v[i - 1]);
}

Method current_method(const LabSession& s) {
    const std::size_t v = std::min<std::size_t>(static_cast<std::size_t>(std::max(0, s.selected_variant)), s.experiment->variant_count() - 1);
    return s.experiment->run(v).model().integrator.method;
}

void start_map(LabSession& s, PanelState& p) {
    StabilitySettings settings;
    settings.method = current_method(s);
    settings.dts = one_two_five(1e-5, 0.5);
    settings.stiffnesses = one_two_five(0.1, 1e4);
    const StabilityBase base = stability_base(s.scene);
    const StabilityGrid defaults = default_stability_grid(false);
    p.stability.start([settings, base, defaults](const std::function<void(double)>& progress, const std::atomic<bool>& cancel) {
        // The map is most of the work (its cells run up to 4000 steps of one particle; the pairs'
        // slice is 216 cells of two): 0.8 of the progress bar, the pairs the rest.
        constexpr double map_share = 0.8;
        StabilityOptions o;
        o.threads = 1;  // leave the other core to the ui and the running experiment
        o.progress = [&progress](double f) { progress(map_share * f); };
        o.cancel = &cancel;
        StabilityMap map;
        map.settings = settings;
        map.cells = stability_map(base, settings.method, settings.dts, settings.stiffnesses, defaults.map_speed,
                                  defaults.map_restitution, defaults.map_radius_fraction, o);
        map.limits = stability_limits(map.cells);
        if (!cancel.load()) {
            o.grid = defaults;
            o.grid.methods = {settings.method};
            o.grid.dts.clear();  // the collision slice alone
            o.grid.sweep_dts.clear();
            o.progress = [&progress](double f) { progress(map_share + (1.0 - map_share) * f); };
            map.pair_cells = run_stability_study(base, o).pair_cells;
        }
        map.cancelled = cancel.load();
        return map;
    });
}

void draw_map(const LabSession& s, const StabilityMap& m, float width) {
    const std::vector<double>& dts = m.settings.dts;
    const std::vector<double>& ks = m.settings.stiffnesses;
    if (dts.size() < 2 || ks.size() < 2) return;
    const double limit = method_stability_limit(m.settings.method);
    std::vector<double> limit_k, limit_dt;
    if (std::isfinite(limit))
        for (double k : {lower_edge(ks, 0), upper_edge(ks, ks.size() - 1)}) {
            limit_k.push_back(k);
            limit_dt.push_back(limit / k);
        }
    const std::size_t v = std::min<std::size_t>(static_cast<std::size_t>(std::max(0, s.selected_variant)), s.experiment->variant_count() - 1);
    const Simulation& sim = s.experiment->run(v);
    // k = 0 (no drag) has no place on a log axis: such a setting sits at the left edge.
    double current_k = std::max(sim.max_drag_stiffness(), ks.front()), current_dt = sim.dt();

    if (!plot::BeginPlot("##stability_map", ImVec2(width, -1), plot::PlotFlags_LogLog | plot::PlotFlags_LegendOutside)) return;
    plot::SetupAxes("drag stiffness k (1/s)", "time step dt (s)");
    for (const StabilityCell& c : m.cells) {
        const auto di = static_cast<std::size_t>(std::find(dts.begin(), dts.end(), c.c.dt) - dts.begin());
        const auto ki = static_cast<std::size_t>(std::find(ks.begin(), ks.end(), c.c.stiffness) - ks.begin());
        if (di >= dts.size() || ki >= ks.size()) continue;
        plot::PlotRect(to_string(c.outcome), lower_edge(ks, ki), lower_edge(dts, di), upper_edge(ks, ki), upper_edge(dts, di),
                       outcome_color(c.outcome));
    }
    if (!limit_k.empty())
        plot::PlotLine("theory: dt k = limit", limit_k.data(), limit_dt.data(), 2, {1.0f, 1.0f, 1.0f, 0.9f}, 2.0f);
    plot::PlotMarkers("##current", &current_k, &current_dt, 1, {1.0f, 1.0f, 1.0f, 1.0f}, plot::Marker::diamond, 6.0f);
    plot::PlotText("current", current_k, current_dt, {1.0f, 1.0f, 1.0f, 1.0f});
    plot::EndPlot();
}

void limits_table(const StabilityMap& m) {
    const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_Borders | ImGuiTableFlags_ScrollY |
                                  ImGuiTableFlags_SizingFixedFit;
    if (!ImGui::BeginTable("##limits", 3, flags, ImVec2(0, ImGui::GetContentRegionAvail().y))) return;
    ImGui::TableSetupScrollFreeze(0, 1);
    ImGui::TableSetupColumn("k (1/s)");
    ImGui::TableSetupColumn("theory dt (s)");
    ImGui::TableSetupColumn("largest stable dt (s)");
    ImGui::TableHeadersRow();
    for (const StabilityLimit& l : m.limits) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::Text("%.3g", l.stiffness);
        ImGui::TableNextColumn();
        if (std::isfinite(l.theoretical_dt)) ImGui::Text("%.3g", l.theoretical_dt);
        else ImGui::TextUnformatted("any");
        ImGui::TableNextColumn();
        if (l.measured_dt) ImGui::Text("%.3g", *l.measured_dt);
        else ImGui::TextUnformatted("none on the grid");
    }
    ImGui::EndTable();
}

ImVec4 to_imvec4(const Rgba& c) { return {c[0], c[1], c[2], 1.0f}; }

// The collision slice: how many cells ended each way, then every cell that did not end stable.
void pairs_table(const StabilityMap& m) {
    if (m.pair_cells.empty()) {
        ImGui::TextDisabled("No collision cells (the computation was cancelled before them).");
        return;
    }
    std::array<int, stability_outcome_count> counts{};
    for (const StabilityCell& c : m.pair_cells) ++counts[static_cast<std::size_t>(c.outcome)];
    ImGui::TextWrapped("Two balls thrown at each other across the room (ball 0 of radius %.2g of the room, ball 1 1 or 10 "
                       "times its radius and 1/1000 to 1000 times its mass), over dt, speed and restitution:",
                       m.pair_cells.front().c.radius_fraction);
    for (std::size_t o = 0; o < counts.size(); ++o) {
        if (o > 0) ImGui::SameLine();
        ImGui::ColorButton(to_string(static_cast<StabilityOutcome>(o)), to_imvec4(outcome_color(static_cast<StabilityOutcome>(o))),
                           ImGuiColorEditFlags_NoTooltip, ImVec2(ImGui::GetFontSize(), ImGui::GetFontSize()));
        ImGui::SameLine();
        ImGui::Text("%s %d", to_string(static_cast<StabilityOutcome>(o)), counts[o]);
    }
    const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_Borders | ImGuiTableFlags_ScrollY |
                                  ImGuiTableFlags_SizingFixedFit;
    if (!ImGui::BeginTable("##pairs", 8, flags, ImVec2(0, ImGui::GetContentRegionAvail().y))) return;
    ImGui::TableSetupScrollFreeze(0, 1);
    for (const char* h : {"dt (s)", "speed (m/s)", "e", "radii", "masses", "outcome", "warned", "what happened"})
        ImGui::TableSetupColumn(h);
    ImGui::TableHeadersRow();
    for (const StabilityCell& c : m.pair_cells) {
        if (c.outcome == StabilityOutcome::stable) continue;
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::Text("%.3g", c.c.dt);
        ImGui::TableNextColumn();
        ImGui::Text("%.3g", c.c.speed);
        ImGui::TableNextColumn();
        ImGui::Text("%.2g", c.c.restitution);
        ImGui::TableNextColumn();
        ImGui::Text("1 : %.3g", c.c.pair_radius_ratio);
        ImGui::TableNextColumn();
        ImGui::Text("1 : %.3g", c.c.pair_mass_ratio);
        ImGui::TableNextColumn();
        ImGui::TextColored(to_imvec4(outcome_color(c.outcome)), "%s", to_string(c.outcome));
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(c.collision_warned ? "yes" : "no");
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(c.detail.c_str());
    }
    ImGui::EndTable();
}

}  // namespace

void draw_stability_tab(LabSession& s) {
    PanelState& p = panels_of(s);
    p.stability.poll();
    const Method method = current_method(s);
    const double limit = method_stability_limit(method);
    ImGui::Text("method %s:", to_string(method));
    ImGui::SameLine();
    if (std::isfinite(limit)) ImGui::TextDisabled("linear decay is stable for dt k < %.3g", limit);
    else ImGui::TextDisabled("stable for any dt k");
    ImGui::SameLine();
    if (p.stability.running()) {
        ImGui::ProgressBar(static_cast<float>(p.stability.progress()), ImVec2(ImGui::GetFontSize() * 8.0f, 0));
        ImGui::SameLine();
        if (ImGui::Button("Cancel##stab")) p.stability.cancel();
    } else {
        if (ImGui::Button("Compute map")) start_map(s, p);
        note_item_rect(s, "stability.compute");
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("One particle launched at 5 m/s from the room's centre (e = 0.5) for every dt and linear-drag\n"
                          "stiffness k = b/m of the grid, classified stable / energy growth / NaN / escaped / jitter /\n"
                          "tunnelled. Runs in the background.");
    if (!p.stability.error().empty()) ImGui::TextColored({1, 0.4f, 0.4f, 1}, "%s", p.stability.error().c_str());
    if (!p.stability.result()) {
        ImGui::TextDisabled("Compute the map to see where this method stays stable.");
        return;
    }
    const StabilityMap& m = *p.stability.result();
    if (m.settings.method != method) {
        ImGui::SameLine();
        ImGui::TextDisabled("(map of %s: compute again)", to_string(m.settings.method));
    }
    if (m.cancelled) {
        ImGui::SameLine();
        ImGui::TextDisabled("(cancelled: part of the map)");
    }
    ImGui::SameLine();
    ImGui::RadioButton("map##stab", &p.stability_view, 0);
    ImGui::SameLine();
    ImGui::RadioButton("limits##stab", &p.stability_view, 1);
    ImGui::SameLine();
    ImGui::RadioButton("collisions##stab", &p.stability_view, 2);
    note_item_rect(s, "stability.collisions");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Pairs thrown at each other on this method: where they end deep in each other or pass through");
    ImGui::SameLine();
    ImGui::Checkbox("own window##stab", &p.stability_window);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Show the map in a window of its own (movable, resizable)");
    if (p.stability_view == 0) draw_map(s, m, -1.0f);
    else if (p.stability_view == 1) limits_table(m);
    else pairs_table(m);
    if (!p.stability_window) return;
    ImGui::SetNextWindowSize(ImVec2(760, 520), ImGuiCond_FirstUseEver);
    if (ImGui::Begin("Stability map", &p.stability_window)) draw_map(s, m, -1.0f);
    ImGui::End();
}

}  // namespace pl::ui
