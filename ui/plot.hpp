// Our plot widget (ImPlot is not packaged here): an ImPlot-shaped immediate-mode API drawn with
// ImDrawList.
//
//     if (plot::BeginPlot("##height", size)) {
//         plot::SetupAxes("time (s)", "height (m)");
//         plot::PlotLine("P1", xs, ys, n, series_color(0));
//         plot::PlotMarkers("P1", bounce_t, nullptr, m, series_color(0), plot::Marker::tick);
//         plot::PlotResult r = plot::EndPlot();
//     }
//
// Data pointers must stay valid until EndPlot, which draws everything at once (so the y axis
// fits this frame's data). A label's text after "##" is an id only; series with the same label
// share one legend entry. Interaction: wheel zooms time (while following it sets the history
// window), drag pans and stops following, ctrl+wheel zooms y, double-click restores follow and
// auto-fit, clicking a legend entry hides the series, right-click opens export options.
#pragma once

#include "ui/palette.hpp"
#include "ui/plot_history.hpp"

#include <imgui.h>

#include <functional>
#include <limits>
#include <set>
#include <string>

namespace pl::ui::plot {

enum PlotFlags : int {
    PlotFlags_None = 0,
    PlotFlags_NoLegend = 1 << 0,
    PlotFlags_NoXLabel = 1 << 1,  // stacked plots label the shared time axis only once
    PlotFlags_LogLog = 1 << 2,    // both axes logarithmic; fits all data (no follow)
    PlotFlags_FitAll = 1 << 3,    // static data: both axes fit everything, no follow mode
    PlotFlags_ExportCsv = 1 << 4, // this frame, EndPlot returns the visible data as CSV
    PlotFlags_LegendOutside = 1 << 5,  // legend to the right of the plot area (short, wide plots)
    PlotFlags_NoHover = 1 << 6,   // no readout or cursor this frame (while a picture is taken)
};

// The x range that stacked plots share (the time axis). Owned by the caller.
struct TimeAxisLink {
    double x_min = 0.0, x_max = 10.0;
    bool follow_latest = true;  // x range tracks the newest sample
    double window_s = 10.0;     // width of the visible history while following (0: everything)
    // The time under the mouse in whichever linked plot is hovered: all of them draw a cursor.
    double hover_x = std::numeric_limits<double>::quiet_NaN();
    ImGuiID hover_owner = 0;
};

enum class Marker { circle, tick, diamond, square, cross };

struct PlotResult {
    bool hovered = false;
    bool export_csv = false;  // the user asked to export: `csv` holds the visible data
    bool export_png = false;  // the user asked for a picture of [frame_min, frame_max]
    std::string csv;
    ImVec2 frame_min, frame_max;  // the whole widget, screen coordinates
    // A left click (press and release without a drag) on the plot area, in data coordinates
    // (linear plots), and the visible ranges (to pick the nearest point in screen terms).
    bool clicked = false;
    double click_x = 0.0, click_y = 0.0;
    double x_min = 0.0, x_max = 1.0, y_min = 0.0, y_max = 1.0;
    ImVec2 area_min, area_max;  // the plot area (inside the axes), screen coordinates
    // Where the data point (x, y) is drawn (linear plots), screen coordinates.
    ImVec2 to_screen(double x, double y) const {
        return {area_min.x + static_cast<float>((x - x_min) / (x_max - x_min)) * (area_max.x - area_min.x),
                area_max.y - static_cast<float>((y - y_min) / (y_max - y_min)) * (area_max.y - area_min.y)};
    }
};

bool BeginPlot(const char* title, const ImVec2& size, int flags = PlotFlags_None);
// Axis labels carry their unit, e.g. "time (s)", "height (m)".
void SetupAxes(const char* x_label, const char* y_label);
void SetupXLink(TimeAxisLink* link);
// Legend visibility shared by several plots (e.g. the stacked ones); default: per plot.
void SetupLegendHidden(std::set<std::string>* hidden);

void PlotLine(const char* label, const double* xs, const double* ys, int count, const Rgba& color, float thickness = 1.5f);
void PlotLine(const char* label, const SampleSeries& series, const Rgba& color, float thickness = 1.5f);
// Lines to the hover readout of the item plotted last, at the hovered sample's x (e.g. the state
// of the particle at that time). Called during the frame; the function may keep references to
// data that lives until EndPlot.
void SetItemDetail(std::function<std::string(double x)> detail);
// Markers at (x, y); with ys == nullptr they are ticks standing on the x axis (event times).
void PlotMarkers(const char* label, const double* xs, const double* ys, int count, const Rgba& color,
                 Marker shape = Marker::circle, float size = 4.0f);
// The area between a lower and an upper series (a min-max range under its mean), filled in
// `color` (give it a low alpha) beneath every line; each series has its own sample times (the
// histories decimate by value). Not in log-log plots.
void PlotBand(const char* label, const SampleSeries& lower, const SampleSeries& upper, const Rgba& color);
// A filled cell [x0, x1] x [y0, y1] in data coordinates (maps, heat maps).
void PlotRect(const char* label, double x0, double y0, double x1, double y1, const Rgba& color);
// A text note at a data point (e.g. "current setting").
void PlotText(const char* text, double x, double y, const Rgba& color);

PlotResult EndPlot();

// Whether a series of this plot's legend is hidden (for callers that want to skip work).
bool IsHidden(const char* label);

ImU32 ToU32(const Rgba& c, float alpha_scale = 1.0f);

}  // namespace pl::ui::plot
