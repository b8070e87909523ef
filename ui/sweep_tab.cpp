// Sweep tab: a study over one or two preset fields (or a Monte Carlo sample of one) of the
// current scene, run in the background by io/sweep_run.hpp, the same code as `particle-lab
// sweep`; a line plot, a heat map or a histogram of one metric, CSV and PNG export. A click on
// a point pins that point's run beside the live one; Shift+click opens its scene live instead.
#include "io/preset_io.hpp"
#include "io/sweep_table.hpp"
#include "ui/panel_state.hpp"
#include "ui/pin_scene.hpp"
#include "ui/plot.hpp"
#include "ui/sections.hpp"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cmath>

namespace pl::ui {
namespace {

// The fields most studies sweep; any other preset path can be typed.
constexpr const char* common_paths[] = {launch_elevation_path, launch_speed_path, "drag.cd", "drag.model",
                                        "contact.restitution", "contact.friction", "particles[0].mass"};

void path_field(const char* id, std::string& path) {
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 11.0f);
    ImGui::InputText((std::string("##path") + id).c_str(), &path);
    ImGui::SameLine();
    if (ImGui::BeginCombo((std::string("##common") + id).c_str(), nullptr, ImGuiComboFlags_NoPreview)) {
        for (const char* c : common_paths)
            if (ImGui::Selectable(c, path == c)) path = c;
        ImGui::EndCombo();
    }
}

void axis_editor(const char* id, SweepAxisChoice& a) {
    path_field(id, a.path);
    ImGui::SameLine();
    int list = a.list ? 1 : 0;
    ImGui::RadioButton((std::string("range##") + id).c_str(), &list, 0);
    ImGui::SameLine();
    ImGui::RadioButton((std::string("list##") + id).c_str(), &list, 1);
    a.list = list == 1;
    ImGui::SameLine();
    const float w = ImGui::GetFontSize() * 4.0f;
    if (a.list) {
        ImGui::SetNextItemWidth(w * 4.0f);
        ImGui::InputText((std::string("values##") + id).c_str(), &a.values);
        return;
    }
    ImGui::SetNextItemWidth(w);
    ImGui::InputDouble((std::string("from##") + id).c_str(), &a.low, 0.0, 0.0, "%g");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(w);
    ImGui::InputDouble((std::string("to##") + id).c_str(), &a.high, 0.0, 0.0, "%g");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(w);
    ImGui::InputInt((std::string("values##n") + id).c_str(), &a.count, 0);
}

void start_sweep(LabSession& s, PanelState& p) {
    SweepSpec spec;
    const std::string error = spec_from_choices(p.sweep_choices, serialize_preset(s.scene), spec);
    p.sweep.start([spec, error](const std::function<void(double)>& progress, const std::atomic<bool>& cancel) {
        SweepRun run;
        run.spec = spec;
        run.error = error;
        if (!error.empty()) return run;
        std::vector<std::size_t> all(spec.plan.point_count());
        for (std::size_t i = 0; i < all.size(); ++i) all[i] = i;
        run.prepared = prepare_sweep(spec, all);
        if (!(run.error = run.prepared.error).empty()) return run;
        SweepRunOptions o;
        o.threads = 1;  // leave the other core to the ui and the running experiment
        o.cancel = &cancel;
        o.progress = [&progress](std::size_t done, std::size_t total) {
            progress(static_cast<double>(done) / static_cast<double>(std::max<std::size_t>(total, 1)));
        };
        run.results = run_sweep(run.prepared, spec.duration_s, o);
        return run;
    });
}

std::size_t shown_variant(const LabSession& s, const SweepRun& r) {
    const std::size_t n = r.prepared.variant_names.empty() ? 1 : r.prepared.variant_names.size();
    return std::min<std::size_t>(static_cast<std::size_t>(std::max(0, s.selected_variant)), n - 1);
}

// The values that make the point, "launch.elevation_deg=35, drag.model=linear".
std::string point_text(const SweepRun& r, std::size_t index) {
    const std::vector<std::string> names = r.spec.plan.column_names(), values = r.spec.plan.point_values(r.prepared.points[index]);
    std::string what;
    for (std::size_t c = 0; c < names.size(); ++c) what += (c ? ", " : "") + names[c] + "=" + values[c];
    return what;
}

// A click pins the point's run (run for the sweep's duration), to compare with the live run and
// other points. The live scene and its edits are untouched.
void pin_point(LabSession& s, const SweepRun& r, std::size_t index) {
    s.status_message = pin_scene(s, r.prepared.scenes[index], r.spec.duration_s, "sweep point " + point_text(r, index));
}

// The point's scene becomes the live scene, as an unsaved edit of the scene the sweep ran over
// (it is that scene with the point's values set). Edits made since the sweep are not dropped.
void open_point(LabSession& s, const SweepRun& r, std::size_t index) {
    if (s.dirty && serialize_preset(s.scene) != r.spec.preset_text) {
        s.status_message = "Not opened: the scene has unsaved edits made after this sweep (save them or sweep again)";
        return;
    }
    const Scene& scene = r.prepared.scenes[index];
    s.apply_scene(scene);
    if (const std::optional<ParticleSpec> p0 = first_particle(scene)) s.launch_velocity = p0->velocity;
    panels_of(s).launch_from_velocity = true;
    s.dirty = true;
    s.status_message = "Opened sweep point " + std::to_string(r.prepared.points[index]) + " (" + point_text(r, index) +
                       ") as an unsaved edit; P pins it";
}

Rgba heat_color(double t) {  // dark blue to yellow
    const auto f = static_cast<float>(std::clamp(t, 0.0, 1.0));
    return {0.15f + 0.8f * f, 0.2f + 0.7f * f, 0.55f - 0.4f * f, 0.9f};
}

// Heat map of two numeric axes; returns the clicked point's index, if any.
std::optional<std::size_t> heat_map(const SweepRun& r, const std::vector<std::optional<double>>& v,
                                    const std::vector<double>& xs, const std::vector<double>& ys, const char* metric,
                                    plot::PlotResult& result) {
    const std::vector<double> xe = cell_edges(xs), ye = cell_edges(ys);
    double lo = INFINITY, hi = -INFINITY;
    for (const auto& x : v)
        if (x) lo = std::min(lo, *x), hi = std::max(hi, *x);
    if (!plot::BeginPlot("##sweep_heat", ImVec2(-1, -1), plot::PlotFlags_FitAll | plot::PlotFlags_NoLegend)) return std::nullopt;
    plot::SetupAxes(r.spec.plan.axes[0].path.c_str(), r.spec.plan.axes[1].path.c_str());
    const std::size_t ny = ys.size();
    for (std::size_t i = 0; i < v.size(); ++i) {
        if (!v[i]) continue;
        const std::size_t p = r.prepared.points[i], ix = p / ny, iy = p % ny;
        plot::PlotRect(metric, xe[ix], ye[iy], xe[ix + 1], ye[iy + 1], heat_color(hi > lo ? (*v[i] - lo) / (hi - lo) : 0.5));
    }
    result = plot::EndPlot();
    if (!result.clicked) return std::nullopt;
    const auto ix = std::upper_bound(xe.begin(), xe.end(), result.click_x) - xe.begin() - 1;
    const auto iy = std::upper_bound(ye.begin(), ye.end(), result.click_y) - ye.begin() - 1;
    if (ix < 0 || iy < 0 || static_cast<std::size_t>(ix) >= xs.size() || static_cast<std::size_t>(iy) >= ny) return std::nullopt;
    const std::size_t point = static_cast<std::size_t>(ix) * ny + static_cast<std::size_t>(iy);
    for (std::size_t i = 0; i < r.prepared.points.size(); ++i)
        if (r.prepared.points[i] == point) return i;
    return std::nullopt;
}

// Line plot, one series per value of the second axis; returns the clicked point's index.
std::optional<std::size_t> line_plot(const SweepRun& r, const std::vector<std::optional<double>>& v, const char* metric,
                                     plot::PlotResult& result) {
    const std::vector<SweepSeries> series = line_series(r.spec.plan, r.prepared, v);
    if (!plot::BeginPlot("##sweep_line", ImVec2(-1, -1), plot::PlotFlags_FitAll | plot::PlotFlags_LegendOutside)) return std::nullopt;
    plot::SetupAxes(r.spec.plan.axes[0].path.c_str(), metric);
    for (std::size_t k = 0; k < series.size(); ++k) {
        const SweepSeries& sr = series[k];
        const std::string label = sr.label.empty() ? std::string(metric) : sr.label;
        const int n = static_cast<int>(sr.x.size());
        plot::PlotLine(label.c_str(), sr.x.data(), sr.y.data(), n, series_color(k));
        plot::PlotMarkers(label.c_str(), sr.x.data(), sr.y.data(), n, series_color(k), plot::Marker::circle, 3.0f);
    }
    result = plot::EndPlot();
    if (!result.clicked) return std::nullopt;
    // The nearest point in screen terms: distances in fractions of the visible ranges.
    const double sx = result.x_max - result.x_min, sy = result.y_max - result.y_min;
    std::optional<std::size_t> best_point;
    double best = 0.03 * 0.03;  // within 3% of the plot
    for (const SweepSeries& sr : series)
        for (std::size_t j = 0; j < sr.x.size(); ++j) {
            const double dx = (sr.x[j] - result.click_x) / sx, dy = (sr.y[j] - result.click_y) / sy;
            if (dx * dx + dy * dy < best) best = dx * dx + dy * dy, best_point = sr.points[j];
        }
    if (best_point)
        for (std::size_t i = 0; i < r.prepared.points.size(); ++i)
            if (r.prepared.points[i] == *best_point) return i;
    return std::nullopt;
}

// Where the first series' best point is drawn ("sweep.best0"), for the GUI tests to click.
void note_best_point(LabSession& s, const SweepRun& r, const std::vector<std::optional<double>>& v,
                     const plot::PlotResult& result) {
    const std::vector<SweepSeries> series = line_series(r.spec.plan, r.prepared, v);
    if (series.empty() || result.area_max.x <= result.area_min.x) return;
    const std::vector<std::optional<double>> y(series[0].y.begin(), series[0].y.end());
    const auto b = best_index(y);
    if (!b) return;
    const ImVec2 at = result.to_screen(series[0].x[*b], series[0].y[*b]);
    s.widget_rects["sweep.best0"] = {at.x - 1.0f, at.y - 1.0f, 2.0f, 2.0f};
}

void histogram_plot(const std::vector<std::optional<double>>& v, const char* metric, plot::PlotResult& result) {
    const std::size_t bins = std::clamp<std::size_t>(static_cast<std::size_t>(std::sqrt(static_cast<double>(v.size()))), 5, 60);
    const Histogram h = histogram(v, bins);
    ImGui::Text("mean %.6g, standard deviation %.6g, %zu samples without the metric", h.mean, h.sd, h.missing);
    if (!plot::BeginPlot("##sweep_hist", ImVec2(-1, -1), plot::PlotFlags_FitAll | plot::PlotFlags_NoLegend)) return;
    plot::SetupAxes(metric, "samples");
    for (std::size_t b = 0; b < h.counts.size(); ++b) {
        const double x0 = h.low + static_cast<double>(b) * h.width;
        plot::PlotRect("samples", x0, 0.0, x0 + h.width, static_cast<double>(h.counts[b]), series_color(0));
    }
    result = plot::EndPlot();
}

void choices_panel(LabSession& s, PanelState& p) {
    SweepChoices& c = p.sweep_choices;
    int mode = c.monte_carlo ? 1 : 0;
    ImGui::RadioButton("grid##sweep", &mode, 0);
    ImGui::SameLine();
    ImGui::RadioButton("Monte Carlo##sweep", &mode, 1);
    c.monte_carlo = mode == 1;
    ImGui::SameLine();
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 4.0f);
    ImGui::InputDouble("duration (s)##sweep", &c.duration_s, 0.0, 0.0, "%g");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 12.0f);
    const std::vector<SweepMetric>& metrics = sweep_metrics();
    p.sweep_metric = std::clamp(p.sweep_metric, 0, static_cast<int>(metrics.size()) - 1);
    if (ImGui::BeginCombo("metric##sweep", metrics[static_cast<std::size_t>(p.sweep_metric)].name)) {
        for (std::size_t m = 0; m < metrics.size(); ++m)
            if (ImGui::Selectable(metrics[m].name, p.sweep_metric == static_cast<int>(m))) p.sweep_metric = static_cast<int>(m);
        ImGui::EndCombo();
    }
    if (c.monte_carlo) {
        path_field("mc", c.sample_path);
        ImGui::SameLine();
        int d = c.distribution == Distribution::normal ? 0 : 1;
        ImGui::RadioButton("normal(mean, sd)", &d, 0);
        ImGui::SameLine();
        ImGui::RadioButton("uniform(low, high)", &d, 1);
        c.distribution = d == 0 ? Distribution::normal : Distribution::uniform;
        const float w = ImGui::GetFontSize() * 4.0f;
        ImGui::SetNextItemWidth(w);
        ImGui::InputDouble("##a", &c.a, 0.0, 0.0, "%g");
        ImGui::SameLine();
        ImGui::SetNextItemWidth(w);
        ImGui::InputDouble("##b", &c.b, 0.0, 0.0, "%g");
        ImGui::SameLine();
        int n = static_cast<int>(c.samples), seed = static_cast<int>(c.seed);
        ImGui::SetNextItemWidth(w);
        if (ImGui::InputInt("samples", &n, 0)) c.samples = static_cast<std::size_t>(std::max(0, n));
        ImGui::SameLine();
        ImGui::SetNextItemWidth(w);
        if (ImGui::InputInt("seed", &seed, 0)) c.seed = static_cast<std::uint64_t>(std::max(0, seed));
        return;
    }
    axis_editor("a1", c.first);
    ImGui::Checkbox("second axis##sweep", &c.two_axes);
    note_item_rect(s, "sweep.two_axes");
    if (c.two_axes) {
        ImGui::SameLine();
        axis_editor("a2", c.second);
    }
}

void run_controls(LabSession& s, PanelState& p) {
    if (p.sweep.running()) {
        ImGui::ProgressBar(static_cast<float>(p.sweep.progress()), ImVec2(ImGui::GetFontSize() * 10.0f, 0));
        ImGui::SameLine();
        if (ImGui::Button("Cancel##sweep")) p.sweep.cancel();
        return;
    }
    if (ImGui::Button("Run sweep")) start_sweep(s, p);
    note_item_rect(s, "sweep.run");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Runs every point over the current scene in the background (one core), as\n"
                          "particle-lab sweep does with the same axes; every point is checked first.");
}

}  // namespace

void draw_sweep_tab(LabSession& s) {
    PanelState& p = panels_of(s);
    p.sweep.poll();
    choices_panel(s, p);
    run_controls(s, p);
    if (!p.sweep.error().empty()) ImGui::TextColored({1, 0.4f, 0.4f, 1}, "%s", p.sweep.error().c_str());
    if (!p.sweep.result()) return;
    const SweepRun& r = *p.sweep.result();
    if (!r.error.empty()) {
        ImGui::SameLine();
        ImGui::TextColored({1, 0.4f, 0.4f, 1}, "%s", r.error.c_str());
        return;
    }
    ImGui::SameLine();
    const bool export_csv = ImGui::Button("CSV##sweep");
    ImGui::SameLine();
    const bool export_png = ImGui::Button("PNG##sweep");
    ImGui::SameLine();
    ImGui::TextDisabled("%zu points%s; variant %zu; click a point to pin its run, Shift+click to open its scene", r.prepared.points.size(),
                        r.results.cancelled ? " (cancelled: part of them ran)" : "", shown_variant(s, r));
    const auto metric = static_cast<std::size_t>(p.sweep_metric);
    const char* name = sweep_metrics()[metric].name;
    const std::vector<std::optional<double>> v = metric_values(r.spec, r.prepared, r.results, metric, shown_variant(s, r));
    plot::PlotResult result;
    std::optional<std::size_t> clicked;
    const SweepPlan& plan = r.spec.plan;
    if (plan.axes.empty()) {
        histogram_plot(v, name, result);
    } else {
        const auto xs = numeric_values(plan.axes[0]);
        const auto ys = plan.axes.size() == 2 ? numeric_values(plan.axes[1]) : std::nullopt;
        if (xs && ys) {
            clicked = heat_map(r, v, *xs, *ys, name, result);
        } else {
            clicked = line_plot(r, v, name, result);
            note_best_point(s, r, v, result);
        }
    }
    if (clicked && ImGui::GetIO().KeyShift) open_point(s, r, *clicked);
    else if (clicked) pin_point(s, r, *clicked);
    if (export_csv || result.export_csv) {
        const SweepHeader header{sweep_id(r.spec), plan.point_count(), Shard{}};
        write_csv(s, export_path(p, "sweep", ".csv"), sweep_csv(header, r.spec, r.prepared, r.results));
    }
    if (export_png || result.export_png) ask_picture(s, export_path(p, "sweep", ".png"), result.frame_min, result.frame_max);
}

SweepSummary sweep_summary(const LabSession& s) {
    SweepSummary out;
    if (!s.panels) return out;
    const PanelState& p = *s.panels;
    out.running = p.sweep.running();
    if (!p.sweep.result() || !p.sweep.result()->error.empty()) return out;
    const SweepRun& r = *p.sweep.result();
    out.points = r.spec.plan.point_count();
    for (const Comparison& c : r.results.points) out.done += c.variants.empty() ? 0 : 1;
    const auto metric = static_cast<std::size_t>(p.sweep_metric);
    const std::vector<std::optional<double>> v = metric_values(r.spec, r.prepared, r.results, metric, shown_variant(s, r));
    for (const SweepSeries& sr : line_series(r.spec.plan, r.prepared, v)) {
        std::vector<std::optional<double>> y(sr.y.begin(), sr.y.end());
        if (const auto b = best_index(y)) out.best.emplace_back(sr.label, sr.x[*b]);
    }
    return out;
}

}  // namespace pl::ui
