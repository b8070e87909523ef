// Internals of the plot widget shared by its source files (plot.cpp: the API and EndPlot's
// phases; plot_draw.cpp: axes, items and legend; plot_interact.cpp: mouse, readout, menu, CSV).
// Not part of the widget's interface (ui/plot.hpp).
#pragma once

#include "ui/plot.hpp"
#include "ui/plot_math.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <set>
#include <string>
#include <unordered_map>
#include <vector>

namespace pl::ui::plot::detail {

inline constexpr double nan = std::numeric_limits<double>::quiet_NaN();

enum class ItemKind { line, markers, rect, text, band };

struct Item {
    ItemKind kind = ItemKind::line;
    std::string legend;  // "" for a series kept out of the legend ("##id")
    const double* xs = nullptr;
    const double* ys = nullptr;
    int count = 0;
    const double *xs_high = nullptr, *ys_high = nullptr;  // band: the upper edge (xs, ys: the lower)
    int count_high = 0;
    ImU32 color = 0;
    float thickness = 1.5f;
    Marker shape = Marker::circle;
    float size = 4.0f;
    double rect[4] = {0, 0, 0, 0};  // x0, y0, x1, y1
    std::string text;
    // Log plots draw from transformed copies; the originals stay for the CSV.
    std::vector<double> log_xs, log_ys;
    std::vector<PlotPoint> points;  // decimated, in plot coordinates
    // A line drawn on the same pixels as an earlier one: the legend names that one, and this one
    // is dashed (dash_style 1, 2, ...: a different pattern for each further coincident line).
    std::string coincides_with;
    int dash_style = 0;
    int zeros_on_log = 0;  // samples <= 0 in a log plot: marked on the x axis, not dropped
    std::function<std::string(double)> detail;  // SetItemDetail: extra readout lines
};

// What a plot remembers between frames (keyed by its id, like ImPlot's context).
struct PlotState {
    TimeAxisLink own_x;
    std::set<std::string> own_hidden;
    bool auto_fit_y = true;
    double y_min = 0.0, y_max = 1.0;
};

struct Context {
    bool active = false;
    ImGuiID id = 0;
    std::string title;
    ImVec2 frame_min, frame_size;
    int flags = 0;
    std::string x_label, y_label;
    TimeAxisLink* x = nullptr;
    std::set<std::string>* hidden = nullptr;
    PlotState* state = nullptr;
    std::vector<Item> items;
};

Context& context();
std::unordered_map<ImGuiID, PlotState>& states();
std::string legend_label(const char* label);
bool has_flag(int flag);
bool item_visible(const Item& item);

// Data -> screen mapping of the plot area.
struct Frame {
    double x0, x1, y0, y1;
    ImVec2 min, max;
    float px(double x) const { return clamp_px(min.x + static_cast<float>((x - x0) / (x1 - x0)) * (max.x - min.x)); }
    float py(double y) const { return clamp_px(max.y - static_cast<float>((y - y0) / (y1 - y0)) * (max.y - min.y)); }
    double data_x(float sx) const { return x0 + (sx - min.x) / static_cast<double>(max.x - min.x) * (x1 - x0); }
    double data_y(float sy) const { return y0 + (max.y - sy) / static_cast<double>(max.y - min.y) * (y1 - y0); }
    // Far-off points (zoomed in a long way) stay finite floats; the clip rect hides them.
    static float clamp_px(float v) { return std::clamp(v, -1e5f, 1e5f); }
};

inline constexpr float nan_f = std::numeric_limits<float>::quiet_NaN();

double to_log(double v);
void to_log_space(Item& item);
const double* plot_xs(const Item& i);
const double* plot_ys(const Item& i);

struct Extent {
    double lo = std::numeric_limits<double>::infinity(), hi = -std::numeric_limits<double>::infinity();
    void add(double v) {
        if (!std::isfinite(v)) return;
        lo = std::min(lo, v);
        hi = std::max(hi, v);
    }
    bool valid() const { return lo <= hi; }
};

// One legend entry per label; min/max is where it was drawn (for clicks).
struct LegendEntry {
    std::string label;
    std::string note;  // e.g. "(dashed, on 'none')": drawn dim after the label
    ImU32 color;
    ImVec2 min, max;
};

// Where EndPlot puts things this frame.
struct PlotLayout {
    Frame frame;
    ImVec2 widget_min, widget_max;
    bool legend_outside = false;
    float entry_w = 0.0f;  // width of one legend column
};

// Colours and sizes taken from the ImGui style once per EndPlot.
struct Style {
    float line_h;
    ImU32 text, dim, grid;
};

// plot_math.cpp-like helpers (plot_draw.cpp)
Extent x_extent(const std::vector<Item>& items, bool sorted);
void pad(double& lo, double& hi, double fraction);
// Marks lines that draw on the same pixels as an earlier one (Item::coincides_with, dash_style).
void mark_coincident(std::vector<Item>& items, double y_per_pixel);
struct AxisTicks {
    std::vector<double> at;  // in plot coordinates (log10 for log axes)
    std::vector<std::string> labels;
    std::string offset;  // added to every label, when not empty (label_ticks)
};
AxisTicks make_ticks(double lo, double hi, float pixels, float pixels_per_tick, bool log);
void draw_axes(ImDrawList* dl, const Context& c, const PlotLayout& l, const AxisTicks& xt, const AxisTicks& yt,
               const Style& s);
void draw_items(ImDrawList* dl, const Context& c, const Frame& f, bool log, const Style& s);
void draw_legend(ImDrawList* dl, const Context& c, const PlotLayout& l, std::vector<LegendEntry>& entries,
                 const Style& s);

// plot_interact.cpp
struct Nearest {
    const Item* item = nullptr;
    double x = 0, y = 0;  // original (not log) values
    ImVec2 at;
    float distance = std::numeric_limits<float>::infinity();
};
Nearest find_nearest(const std::vector<Item>& items, const Frame& f, ImVec2 mouse, bool sorted);
std::string visible_csv(const Context& c, double x0, double x1, bool log);
// Mouse and wheel on the plot area and legend; returns the legend entry under the mouse.
const LegendEntry* interact(Context& c, const Frame& f, const std::vector<LegendEntry>& entries, bool legend_outside,
                            bool fit_all, PlotResult& result);
void hover_readout(Context& c, const Frame& f, const LegendEntry* over_entry, bool fit_all, bool hovered,
                   const Style& s);
void context_menu(Context& c, bool fit_all, PlotResult& result);

}  // namespace pl::ui::plot::detail
