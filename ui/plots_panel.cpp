// The plots region: height, speed and kinetic energy against time (one line per particle or per
// variant, bounce marks), and the energy ledger of the selected variant.
#include "ui/frame_recorder.hpp"
#include "ui/lab_ui.hpp"
#include "ui/palette.hpp"
#include "ui/panel_state.hpp"
#include "ui/pinned_runs.hpp"
#include "ui/plot.hpp"
#include "ui/sections.hpp"

#include <fmt/format.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>

#include <fstream>
#include <string>
#include <vector>

namespace pl::ui {
namespace {

enum class Quantity { height, speed, kinetic };

struct Line {
    std::string label;
    const SampleSeries* series;
    Rgba color;
    float thickness = 1.5f;
    const ParticleTrack* track = nullptr;  // the hover readout's state of the particle
    const PathSeries* path = nullptr;
};

// The sample of `s` at or just before t (the first one before the series starts).
double value_at(const SampleSeries& s, double t) {
    if (s.empty()) return std::nan("");
    const double* end = s.times() + s.size();
    const std::ptrdiff_t k = std::upper_bound(s.times(), end, t) - s.times();
    return s.values()[static_cast<std::size_t>(std::max<std::ptrdiff_t>(0, k - 1))];
}

// What the hover readout adds on a particle's curve: its state at the hovered time.
std::string particle_state_at(const ParticleTrack& track, const PathSeries* path, double t) {
    std::string out = fmt::format("t = {:.4f} s\nheight {:.4g} m\nspeed {:.4g} m/s\nkinetic energy {:.4g} J", t,
                                  value_at(track.height, t), value_at(track.speed, t), value_at(track.kinetic, t));
    if (path && path->size() > 0) {
        std::size_t k = 0;
        while (k + 1 < path->size() && path->time(k + 1) <= t) ++k;
        const Vec3& p = path->position(k);
        out += fmt::format("\nposition ({:.3f}, {:.3f}, {:.3f}) m at t = {:.3f} s", p.x, p.y, p.z, path->time(k));
    }
    return out;
}

struct Marks {
    std::string label;
    std::vector<double> times;
    Rgba color;
};

struct Band {
    std::string label;
    const SampleSeries *lower, *upper;
    Rgba color;
};

struct MotionSeries {
    std::vector<Line> lines[3];  // per Quantity
    std::vector<Band> bands[3];
    std::vector<Marks> marks;
    bool aggregated = false;
};

const SampleSeries& particle_series(const ParticleTrack& t, Quantity q) {
    return q == Quantity::height ? t.height : q == Quantity::speed ? t.speed : t.kinetic;
}

// Pinned runs, faded and thinner, under their own labels: the selected particle's curves (the
// aggregates' means in a scene of many particles).
void add_pinned_lines(const LabSession& s, std::size_t particle, MotionSeries& out) {
    const PinBoard* board = pins_if_any(s);
    if (!board) return;
    for (const PinnedRun& run : board->runs) {
        const Rgba c = pin_color(run.number);
        if (out.aggregated) {
            out.lines[0].push_back({run.label, &run.aggregate.height_mean, c, 1.2f});
            out.lines[1].push_back({run.label, &run.aggregate.speed_mean, c, 1.2f});
            out.lines[2].push_back({run.label, &run.aggregate.kinetic_total, c, 1.2f});
        } else if (particle < run.particles.size()) {
            const PathSeries* path = particle < run.paths.size() ? &run.paths[particle] : nullptr;
            for (int q = 0; q < 3; ++q)
                out.lines[q].push_back({run.label, &particle_series(run.particles[particle], static_cast<Quantity>(q)), c, 1.2f,
                                        &run.particles[particle], path});
        }
    }
}

// Which lines the motion plots show: per variant (the selected particle) when there are several
// variants, else per particle; aggregates when there are too many particles to draw one by one.
MotionSeries motion_series(const LabSession& s, const PlotHistory& h) {
    MotionSeries out;
    const std::size_t variants = h.variants.size();
    out.aggregated = h.aggregated();
    const std::size_t sel = s.selected_particle < 0 ? 0 : static_cast<std::size_t>(s.selected_particle);
    if (out.aggregated) {
        for (std::size_t v = 0; v < variants; ++v) {
            const AggregateTrack& a = h.variants[v].aggregate;
            const std::string name = variants > 1 ? variant_name(s, v) : std::string("all particles");
            const Rgba c = series_color(static_cast<int>(v));
            Rgba faint = c;
            faint[3] = 0.45f;
            Rgba shade = c;
            shade[3] = 0.16f;
            out.bands[0].push_back({name + "##range", &a.height_min, &a.height_max, shade});
            out.lines[0].push_back({name + "##mean", &a.height_mean, c, 2.0f});
            out.lines[0].push_back({name + "##min", &a.height_min, faint, 1.0f});
            out.lines[0].push_back({name + "##max", &a.height_max, faint, 1.0f});
            out.bands[1].push_back({name + "##range", &a.speed_min, &a.speed_max, shade});
            out.lines[1].push_back({name + "##mean", &a.speed_mean, c, 2.0f});
            out.lines[1].push_back({name + "##min", &a.speed_min, faint, 1.0f});
            out.lines[1].push_back({name + "##max", &a.speed_max, faint, 1.0f});
            out.lines[2].push_back({name, &a.kinetic_total, c, 2.0f});
        }
        add_pinned_lines(s, sel, out);
        return out;
    }
    std::vector<int> mark_index;  // (variant, particle) -> index into out.marks
    if (variants > 1) {
        for (std::size_t v = 0; v < variants; ++v) {
            if (sel >= h.variants[v].particles.size()) continue;
            const std::string name = variant_name(s, v);
            const Rgba c = series_color(static_cast<int>(v));
            for (int q = 0; q < 3; ++q)
                out.lines[q].push_back({name, &particle_series(h.variants[v].particles[sel], static_cast<Quantity>(q)), c, 1.5f,
                                        &h.variants[v].particles[sel], &h.variants[v].paths[sel]});
            out.marks.push_back({name, {}, c});
        }
        for (const LoggedEvent& e : h.events)
            if (e.event.particle == sel && e.variant < out.marks.size() &&
                (e.event.kind == EventKind::bounce || e.event.kind == EventKind::rest))
                out.marks[e.variant].times.push_back(e.event.t);
    } else if (variants == 1) {
        const std::vector<ParticleTrack>& tracks = h.variants[0].particles;
        for (std::size_t i = 0; i < tracks.size(); ++i) {
            const std::string name = "particle " + std::to_string(i);
            const Rgba c = series_color(static_cast<int>(i));
            const float width = i == sel && tracks.size() > 1 ? 2.5f : 1.5f;
            for (int q = 0; q < 3; ++q)
                out.lines[q].push_back({name, &particle_series(tracks[i], static_cast<Quantity>(q)), c, width, &tracks[i],
                                        &h.variants[0].paths[i]});
            out.marks.push_back({name, {}, c});
        }
        for (const LoggedEvent& e : h.events)
            if (e.event.particle < out.marks.size() && (e.event.kind == EventKind::bounce || e.event.kind == EventKind::rest))
                out.marks[e.event.particle].times.push_back(e.event.t);
    }
    add_pinned_lines(s, sel, out);
    return out;
}

// A picture is taken two frames after it was asked for, once the menu that asked is closed.
void pending_picture(LabSession& s) {
    PendingPicture& pic = panels_of(s).picture;
    if (pic.frames_left < 0) return;
    if (pic.frames_left-- > 0) return;
    s.requests.screenshot = true;
    s.requests.screenshot_path = pic.path;
    s.requests.crop_x = pic.min.x;
    s.requests.crop_y = pic.min.y;
    s.requests.crop_w = pic.max.x - pic.min.x;
    s.requests.crop_h = pic.max.y - pic.min.y;
    s.status_message = "Wrote " + pic.path.string();
    pic.frames_left = -1;
}

void handle_result(LabSession& s, const plot::PlotResult& r, const std::string& name) {
    PanelState& p = panels_of(s);
    if (r.export_csv) write_csv(s, export_path(p, name, ".csv"), r.csv);
    if (r.export_png) ask_picture(s, export_path(p, name, ".png"), r.frame_min, r.frame_max);
}

void toolbar(LabSession& s, PanelState& p, bool& export_csv, bool& export_png) {
    plot::TimeAxisLink& axis = p.time_axis;
    // No tooltips while a picture is pending: the mouse is still on the button that asked.
    const bool quiet = p.picture.frames_left >= 0;
    auto tip = [quiet](const std::string& text) {
        if (!quiet && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", text.c_str());
    };
    ImGui::Checkbox("follow", &axis.follow_latest);
    tip("Follow the newest samples. Drag a plot to scroll back in time, wheel to zoom, double-click to follow again.");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 5.0f);
    double window = axis.window_s;
    if (ImGui::InputDouble("window (s)", &window, 0.0, 0.0, window > 0.0 ? "%.3g" : "all", ImGuiInputTextFlags_EnterReturnsTrue))
        axis.window_s = std::clamp(window, 0.0, 1e7);
    tip("Seconds of history shown while following (0: all of it)");
    ImGui::SameLine();
    if (ImGui::SmallButton("all")) {
        axis.window_s = 0.0;
        axis.follow_latest = true;
    }
    ImGui::SameLine();
    ImGui::Checkbox("bounces", &p.show_event_markers);
    tip("Mark bounces and rests with ticks on the time axis");
    ImGui::SameLine();
    export_csv = ImGui::SmallButton("CSV");
    tip("Export the visible data of these plots to " + export_path(p, "<plot>", ".csv").string());
    ImGui::SameLine();
    export_png = ImGui::SmallButton("PNG");
    ui::note_item_rect(s, "plots.png");
    tip("Save a picture of the plots to " + export_path(p, "plots", ".png").string());
    ImGui::SameLine();
    if (ImGui::SmallButton("to...")) begin_choose_export_folder(s);
    tip("Choose the folder exports go to (now " + export_path(p, "", "").parent_path().string() + ")");
}

void motion_plots(LabSession& s, PanelState& p, const PlotHistory& h, bool export_csv) {
    const MotionSeries ms = motion_series(s, h);
    static const char* ids[3] = {"##height", "##speed", "##kinetic"};
    static const char* names[3] = {"height", "speed", "kinetic"};
    const char* y_labels[3] = {ms.aggregated ? "height: mean, min-max range (m)" : "height (m)",
                               ms.aggregated ? "speed: mean, min-max range (m/s)" : "speed (m/s)",
                               ms.aggregated ? "total kinetic energy (J)" : "kinetic energy (J)"};
    const float spacing = ImGui::GetStyle().ItemSpacing.y;
    const float avail = ImGui::GetContentRegionAvail().y;
    const float each = std::max(80.0f, (avail - 2 * spacing) / 3.0f);
    for (int q = 0; q < 3; ++q) {
        int flags = plot::PlotFlags_None;
        if (q < 2) flags |= plot::PlotFlags_NoXLabel;
        if (q > 0) flags |= plot::PlotFlags_NoLegend;
        if (export_csv) flags |= plot::PlotFlags_ExportCsv;
        if (p.picture.frames_left >= 0) flags |= plot::PlotFlags_NoHover;
        if (!plot::BeginPlot(ids[q], ImVec2(-1, each), flags)) continue;
        plot::SetupAxes("time (s)", y_labels[q]);
        plot::SetupXLink(&p.time_axis);
        plot::SetupLegendHidden(&p.hidden_series);
        for (const Band& b : ms.bands[q]) plot::PlotBand(b.label.c_str(), *b.lower, *b.upper, b.color);
        for (const Line& l : ms.lines[q]) {
            plot::PlotLine(l.label.c_str(), *l.series, l.color, l.thickness);
            if (l.track) plot::SetItemDetail([&l](double t) { return particle_state_at(*l.track, l.path, t); });
        }
        if (p.show_event_markers)
            for (const Marks& m : ms.marks)
                plot::PlotMarkers(m.label.c_str(), m.times.data(), nullptr, static_cast<int>(m.times.size()), m.color,
                                  plot::Marker::tick, 3.0f);
        handle_result(s, plot::EndPlot(), names[q]);
    }
}

void ledger_plots(LabSession& s, PanelState& p, const PlotHistory& h, bool export_csv) {
    if (h.variants.empty()) return;
    if (s.selected_variant < 0 || static_cast<std::size_t>(s.selected_variant) >= h.variants.size()) s.selected_variant = 0;
    const std::size_t v = static_cast<std::size_t>(s.selected_variant);
    if (h.variants.size() > 1) {
        ImGui::SetNextItemWidth(ImGui::GetFontSize() * 12.0f);
        if (ImGui::BeginCombo("variant", variant_name(s, v).c_str())) {
            for (std::size_t k = 0; k < h.variants.size(); ++k)
                if (ImGui::Selectable(variant_name(s, k).c_str(), k == v)) s.selected_variant = static_cast<int>(k);
            ImGui::EndCombo();
        }
    }
    const LedgerTrack& l = h.variants[v].ledger;
    const Model& m = s.experiment->run(v).model();
    const float avail = ImGui::GetContentRegionAvail().y;
    const float top = std::max(100.0f, avail * 0.62f);
    const int quiet = p.picture.frames_left >= 0 ? plot::PlotFlags_NoHover : 0;
    int flags = plot::PlotFlags_NoXLabel | quiet | (export_csv ? plot::PlotFlags_ExportCsv : 0);
    if (plot::BeginPlot("##ledger", ImVec2(-1, top), flags)) {
        plot::SetupAxes("time (s)", "energy (J), all particles");
        plot::SetupXLink(&p.time_axis);
        plot::PlotLine("kinetic", l.kinetic, series_color(0), 2.0f);
        plot::PlotLine("potential", l.potential, series_color(1), 2.0f);
        plot::PlotLine("lost in bounces", l.bounce, series_color(3));
        plot::PlotLine("lost to friction", l.friction, series_color(5));
        if (m.drag.model != DragModel::none) plot::PlotLine("lost to drag", l.drag, series_color(4));
        if (m.world.wind.kind != WindKind::none && m.drag.model != DragModel::none)
            plot::PlotLine("work by wind", l.wind_work, series_color(9));
        handle_result(s, plot::EndPlot(), "ledger");
    }
    flags = quiet | (export_csv ? plot::PlotFlags_ExportCsv : plot::PlotFlags_None);
    if (plot::BeginPlot("##residual", ImVec2(-1, -1), flags)) {
        plot::SetupAxes("time (s)", "residual E0 + W_wind - (KE + PE + lost) (J)");
        plot::SetupXLink(&p.time_axis);
        plot::PlotLine("residual (integrator error)", l.residual, series_color(7), 1.5f);
        handle_result(s, plot::EndPlot(), "residual");
    }
}

}  // namespace

std::filesystem::path export_path(const PanelState& p, const std::string& plot, const char* extension) {
    const std::string name = p.export_stem + "-" + plot + extension;
    return std::filesystem::absolute(p.export_dir.empty() ? std::filesystem::path(name) : p.export_dir / name);
}

void draw_plots_panel(LabSession& s) {
    if (!s.experiment) return;
    PanelState& p = panels_of(s);
    const PlotHistory& h = history_of(s);
    pending_picture(s);
    bool export_csv = false, export_png = false;
    toolbar(s, p, export_csv, export_png);
    const ImVec2 region_min = ImGui::GetCursorScreenPos();
    if (ImGui::BeginTabBar("##plot_tabs")) {
        if (ImGui::BeginTabItem("Height, speed, energy")) {
            p.plots_tab = 0;
            motion_plots(s, p, h, export_csv);
            ImGui::EndTabItem();
        }
        if (ImGui::BeginTabItem("Energy ledger")) {
            p.plots_tab = 1;
            ledger_plots(s, p, h, export_csv);
            ImGui::EndTabItem();
        }
        ImGui::EndTabBar();
    }
    if (export_csv && !export_question_open(s)) {
        // handle_result wrote one file per plot; name them all in the status line.
        s.status_message = "Wrote " + export_path(p, p.plots_tab == 0 ? "{height,speed,kinetic}" : "{ledger,residual}", ".csv").string();
    }
    if (export_png) {
        const ImVec2 region_max{ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x, ImGui::GetCursorScreenPos().y};
        ask_picture(s, export_path(p, "plots", ".png"), region_min, region_max);
    }
}

}  // namespace pl::ui
