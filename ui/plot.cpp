#include "ui/plot.hpp"

#include "ui/plot_math.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <unordered_map>
#include <vector>

namespace pl::ui::plot {
namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

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

Context& context() {
    static Context c;
    return c;
}

std::unordered_map<ImGuiID, PlotState>& states() {
    static std::unordered_map<ImGuiID, PlotState> s;
    return s;
}

std::string legend_label(const char* label) {
    const char* hash = std::strstr(label, "##");
    return hash ? std::string(label, hash) : std::string(label);
}

bool has_flag(int flag) { return (context().flags & flag) != 0; }

bool item_visible(const Item& item) {
    const Context& c = context();
    return item.legend.empty() || c.hidden->count(item.legend) == 0;
}

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

constexpr float nan_f = std::numeric_limits<float>::quiet_NaN();

double to_log(double v) { return v > 0.0 ? std::log10(v) : nan; }

void to_log_space(Item& item) {
    if (item.kind == ItemKind::rect) {
        for (double& v : item.rect) v = to_log(v);
        return;
    }
    item.log_xs.resize(static_cast<std::size_t>(item.count));
    for (int i = 0; i < item.count; ++i) item.log_xs[static_cast<std::size_t>(i)] = to_log(item.xs[i]);
    if (item.ys) {
        item.log_ys.resize(static_cast<std::size_t>(item.count));
        for (int i = 0; i < item.count; ++i) item.log_ys[static_cast<std::size_t>(i)] = to_log(item.ys[i]);
    }
}

const double* plot_xs(const Item& i) { return i.log_xs.empty() ? i.xs : i.log_xs.data(); }
const double* plot_ys(const Item& i) { return i.log_ys.empty() ? i.ys : i.log_ys.data(); }

struct Extent {
    double lo = std::numeric_limits<double>::infinity(), hi = -std::numeric_limits<double>::infinity();
    void add(double v) {
        if (!std::isfinite(v)) return;
        lo = std::min(lo, v);
        hi = std::max(hi, v);
    }
    bool valid() const { return lo <= hi; }
};

// Every item's x extent; lines are sorted by x unless the plot fits all data.
Extent x_extent(const std::vector<Item>& items, bool sorted) {
    Extent e;
    for (const Item& item : items) {
        if (!item_visible(item)) continue;
        if (item.kind == ItemKind::rect) {
            e.add(item.rect[0]);
            e.add(item.rect[2]);
            continue;
        }
        if (item.count <= 0) continue;
        const double* xs = plot_xs(item);
        if (sorted && item.kind == ItemKind::line) {
            e.add(xs[0]);
            e.add(xs[item.count - 1]);
        } else {
            for (int i = 0; i < item.count; ++i) e.add(xs[i]);
        }
    }
    return e;
}

void pad(double& lo, double& hi, double fraction) {
    if (hi > lo) {
        const double m = (hi - lo) * fraction;
        lo -= m;
        hi += m;
        return;
    }
    const double half = std::max(std::abs(lo) * 0.1, 1e-9);
    lo -= half;
    hi += half;
}

std::string log_label(double v) {
    char buf[32];
    if (v >= 1e-3 && v < 1e4) std::snprintf(buf, sizeof buf, "%g", v);
    else std::snprintf(buf, sizeof buf, "%.0e", v);
    return buf;
}

struct AxisTicks {
    std::vector<double> at;  // in plot coordinates (log10 for log axes)
    std::vector<std::string> labels;
};

AxisTicks make_ticks(double lo, double hi, float pixels, float pixels_per_tick, bool log) {
    AxisTicks t;
    if (log) {
        const Ticks ticks = log_ticks(std::pow(10.0, lo), std::pow(10.0, hi));
        // Keep every k-th tick so labels never crowd a short axis.
        const std::size_t room = std::max<std::size_t>(2, static_cast<std::size_t>(pixels / pixels_per_tick));
        const std::size_t stride = (ticks.values.size() + room - 1) / room;
        for (std::size_t i = 0; i < ticks.values.size(); ++i) {
            const double v = ticks.values[i];
            const long exponent = std::lround(std::floor(std::log10(v) + 1e-9));
            if (stride > 1 && (std::abs(v / std::pow(10.0, exponent) - 1.0) > 1e-9 || exponent % static_cast<long>(stride) != 0))
                continue;
            t.at.push_back(std::log10(v));
            t.labels.push_back(log_label(v));
        }
        return t;
    }
    const int target = std::max(2, static_cast<int>(pixels / pixels_per_tick));
    const Ticks ticks = nice_ticks(lo, hi, target);
    for (double v : ticks.values) {
        t.at.push_back(v);
        t.labels.push_back(format_tick(v, ticks.step));
    }
    return t;
}

void draw_marker(ImDrawList* dl, ImVec2 p, Marker shape, float r, ImU32 col) {
    switch (shape) {
        case Marker::circle: dl->AddCircleFilled(p, r, col, 12); break;
        case Marker::tick: dl->AddLine({p.x, p.y - r}, {p.x, p.y + r}, col, 1.5f); break;
        case Marker::diamond:
            dl->AddQuadFilled({p.x, p.y - r}, {p.x + r, p.y}, {p.x, p.y + r}, {p.x - r, p.y}, col);
            break;
        case Marker::square: dl->AddRectFilled({p.x - r, p.y - r}, {p.x + r, p.y + r}, col); break;
        case Marker::cross:
            dl->AddLine({p.x - r, p.y - r}, {p.x + r, p.y + r}, col, 2.0f);
            dl->AddLine({p.x - r, p.y + r}, {p.x + r, p.y - r}, col, 2.0f);
            break;
    }
}

void draw_polyline(ImDrawList* dl, const Frame& f, const std::vector<PlotPoint>& points, ImU32 col, float thickness) {
    static std::vector<ImVec2> run;
    auto flush = [&] {
        if (run.size() >= 2) dl->AddPolyline(run.data(), static_cast<int>(run.size()), col, ImDrawFlags_None, thickness);
        else if (run.size() == 1) dl->AddCircleFilled(run[0], thickness, col, 6);
        run.clear();
    };
    run.clear();
    for (const PlotPoint& p : points) {
        if (!std::isfinite(p.y) || !std::isfinite(p.x)) {
            flush();
            continue;
        }
        run.push_back({f.px(p.x), f.py(p.y)});
    }
    flush();
}

std::string csv_field(const std::string& s) {
    if (s.find_first_of(",\"\n") == std::string::npos) return s;
    std::string out = "\"";
    for (char ch : s) {
        if (ch == '"') out += '"';
        out += ch;
    }
    return out + "\"";
}

std::string visible_csv(const Context& c, double x0, double x1, bool log) {
    if (log) {
        x0 = std::pow(10.0, x0);
        x1 = std::pow(10.0, x1);
    }
    std::string out = "series," + csv_field(c.x_label) + "," + csv_field(c.y_label) + "\n";
    // Shortest form that reads back to the same double.
    auto append = [&out](double v) {
        char buf[32];
        const auto r = std::to_chars(buf, buf + sizeof buf, v);
        out.append(buf, r.ptr);
    };
    for (const Item& item : c.items) {
        if (!item_visible(item) || !item.ys || (item.kind != ItemKind::line && item.kind != ItemKind::markers)) continue;
        const std::string name = csv_field(item.legend);
        for (int i = 0; i < item.count; ++i) {
            if (item.xs[i] < x0 || item.xs[i] > x1) continue;
            out += name;
            out += ',';
            append(item.xs[i]);
            out += ',';
            append(item.ys[i]);
            out += '\n';
        }
    }
    return out;
}

struct Nearest {
    const Item* item = nullptr;
    double x = 0, y = 0;  // original (not log) values
    ImVec2 at;
    float distance = std::numeric_limits<float>::infinity();
};

// The sample closest to the mouse (in pixels) among the visible lines and markers.
Nearest find_nearest(const std::vector<Item>& items, const Frame& f, ImVec2 mouse, bool sorted) {
    Nearest best;
    auto consider = [&](const Item& item, int i) {
        const double* xs = plot_xs(item);
        const double* ys = plot_ys(item);
        if (!std::isfinite(xs[i]) || !std::isfinite(ys[i])) return;
        const ImVec2 p{f.px(xs[i]), f.py(ys[i])};
        const float d = std::hypot(p.x - mouse.x, p.y - mouse.y);
        if (d < best.distance) best = {&item, item.xs[i], item.ys[i], p, d};
    };
    const double mx = f.data_x(mouse.x);
    const double pixel = (f.x1 - f.x0) / std::max(1.0f, f.max.x - f.min.x);
    for (const Item& item : items) {
        if (!item_visible(item) || !item.ys || item.count <= 0) continue;
        if (item.kind != ItemKind::line && item.kind != ItemKind::markers) continue;
        const double* xs = plot_xs(item);
        if (!sorted || item.kind != ItemKind::line) {
            for (int i = 0; i < item.count; ++i) consider(item, i);
            continue;
        }
        // Samples within a few pixels of the mouse column (bounded, so 100k points stay cheap).
        const int lo = static_cast<int>(std::lower_bound(xs, xs + item.count, mx - 8 * pixel) - xs);
        const int hi = static_cast<int>(std::upper_bound(xs, xs + item.count, mx + 8 * pixel) - xs);
        const int step = std::max(1, (hi - lo) / 256);
        for (int i = std::max(0, lo - 1); i < std::min(item.count, hi + 1); i += step) consider(item, i);
    }
    return best;
}

}  // namespace

ImU32 ToU32(const Rgba& c, float alpha_scale) {
    return ImGui::ColorConvertFloat4ToU32(ImVec4(c[0], c[1], c[2], c[3] * alpha_scale));
}

bool BeginPlot(const char* title, const ImVec2& size, int flags) {
    Context& c = context();
    IM_ASSERT(!c.active && "BeginPlot without EndPlot");
    const ImVec2 avail = ImGui::GetContentRegionAvail();
    ImVec2 s{size.x > 0 ? size.x : std::max(avail.x, 50.0f), size.y > 0 ? size.y : std::max(avail.y, 50.0f)};
    if (size.x < 0) s.x = std::max(50.0f, avail.x + size.x);
    if (size.y < 0) s.y = std::max(50.0f, avail.y + size.y);
    c.id = ImGui::GetID(title);
    c.title = legend_label(title);
    c.frame_min = ImGui::GetCursorScreenPos();
    c.frame_size = s;
    c.flags = flags;
    c.x_label.clear();
    c.y_label.clear();
    c.state = &states()[c.id];
    c.x = &c.state->own_x;
    c.hidden = &c.state->own_hidden;
    c.items.clear();
    c.active = true;
    ImGui::PushID(static_cast<int>(c.id));
    return true;
}

void SetupAxes(const char* x_label, const char* y_label) {
    context().x_label = x_label ? x_label : "";
    context().y_label = y_label ? y_label : "";
}

void SetupXLink(TimeAxisLink* link) {
    if (link) context().x = link;
}

void SetupLegendHidden(std::set<std::string>* hidden) {
    if (hidden) context().hidden = hidden;
}

bool IsHidden(const char* label) {
    const std::string l = legend_label(label);
    return !l.empty() && context().hidden->count(l) > 0;
}

void PlotLine(const char* label, const double* xs, const double* ys, int count, const Rgba& color, float thickness) {
    Item item;
    item.kind = ItemKind::line;
    item.legend = legend_label(label);
    item.xs = xs;
    item.ys = ys;
    item.count = std::max(0, count);
    item.color = ToU32(color);
    item.thickness = thickness;
    context().items.push_back(std::move(item));
}

void PlotLine(const char* label, const SampleSeries& series, const Rgba& color, float thickness) {
    PlotLine(label, series.times(), series.values(), static_cast<int>(series.size()), color, thickness);
}

void PlotMarkers(const char* label, const double* xs, const double* ys, int count, const Rgba& color, Marker shape,
                 float size) {
    Item item;
    item.kind = ItemKind::markers;
    item.legend = legend_label(label);
    item.xs = xs;
    item.ys = ys;
    item.count = std::max(0, count);
    item.color = ToU32(color);
    item.shape = shape;
    item.size = size;
    context().items.push_back(std::move(item));
}

void PlotBand(const char* label, const SampleSeries& lower, const SampleSeries& upper, const Rgba& color) {
    Item item;
    item.kind = ItemKind::band;
    item.legend = legend_label(label);
    item.xs = lower.times();
    item.ys = lower.values();
    item.count = static_cast<int>(lower.size());
    item.xs_high = upper.times();
    item.ys_high = upper.values();
    item.count_high = static_cast<int>(upper.size());
    item.color = ToU32(color);
    context().items.push_back(std::move(item));
}

void PlotRect(const char* label, double x0, double y0, double x1, double y1, const Rgba& color) {
    Item item;
    item.kind = ItemKind::rect;
    item.legend = legend_label(label);
    item.rect[0] = std::min(x0, x1);
    item.rect[1] = std::min(y0, y1);
    item.rect[2] = std::max(x0, x1);
    item.rect[3] = std::max(y0, y1);
    item.color = ToU32(color);
    context().items.push_back(std::move(item));
}

void PlotText(const char* text, double x, double y, const Rgba& color) {
    Item item;
    item.kind = ItemKind::text;
    item.text = text;
    item.rect[0] = x;
    item.rect[1] = y;
    item.color = ToU32(color);
    context().items.push_back(std::move(item));
}

// A band as one trapezoid per pixel column: the lowest sample of the lower series and the
// highest of the upper one in that column (where only one of them has a sample there, the
// other keeps its last value), so a long history costs no more than the plot is wide.
void draw_band(ImDrawList* dl, const Frame& f, const Item& item) {
    const int columns = std::max(1, static_cast<int>(f.max.x - f.min.x));
    std::vector<float> low(static_cast<std::size_t>(columns), nan_f), high(static_cast<std::size_t>(columns), nan_f);
    auto fill = [&](const double* xs, const double* ys, int count, std::vector<float>& out, bool lower) {
        const int first = static_cast<int>(std::lower_bound(xs, xs + count, f.x0) - xs);
        const int last = static_cast<int>(std::upper_bound(xs, xs + count, f.x1) - xs);
        for (int i = first; i < last; ++i) {
            if (!std::isfinite(ys[i])) continue;
            const int col = std::clamp(static_cast<int>(f.px(xs[i]) - f.min.x), 0, columns - 1);
            const float y = f.py(ys[i]);  // screen y grows downwards
            float& v = out[static_cast<std::size_t>(col)];
            v = std::isnan(v) ? y : lower ? std::max(v, y) : std::min(v, y);
        }
    };
    fill(item.xs, item.ys, item.count, low, true);
    fill(item.xs_high, item.ys_high, item.count_high, high, false);
    float prev_x = 0.0f, prev_low = nan_f, prev_high = nan_f;
    for (int col = 0; col < columns; ++col) {
        const float col_low = low[static_cast<std::size_t>(col)], col_high = high[static_cast<std::size_t>(col)];
        if (std::isnan(col_low) && std::isnan(col_high)) continue;  // no sample in this column
        const float l = std::isnan(col_low) ? prev_low : col_low;
        const float h = std::isnan(col_high) ? prev_high : col_high;
        if (std::isnan(l) || std::isnan(h)) continue;  // one edge has had no sample yet
        const float x = f.min.x + static_cast<float>(col);
        if (!std::isnan(prev_low) && !std::isnan(prev_high)) {
            const ImVec2 quad[4] = {{prev_x, prev_high}, {x, h}, {x, l}, {prev_x, prev_low}};
            dl->AddConvexPolyFilled(quad, 4, item.color);
        }
        prev_x = x;
        prev_low = l;
        prev_high = h;
    }
}

PlotResult EndPlot() {
    Context& c = context();
    IM_ASSERT(c.active && "EndPlot without BeginPlot");
    PlotState& st = *c.state;
    TimeAxisLink& link = *c.x;
    const bool log = has_flag(PlotFlags_LogLog);
    const bool fit_all = log || has_flag(PlotFlags_FitAll);
    ImGuiIO& io = ImGui::GetIO();
    ImDrawList* dl = ImGui::GetWindowDrawList();
    const float line_h = ImGui::GetTextLineHeight();
    const ImU32 text_col = ImGui::GetColorU32(ImGuiCol_Text);
    const ImU32 dim_col = ImGui::GetColorU32(ImGuiCol_TextDisabled);
    const ImU32 grid_col = ImGui::GetColorU32(ImGuiCol_TextDisabled, 0.22f);
    PlotResult result;

    if (log) {
        for (Item& item : c.items) {
            if (item.kind == ItemKind::text) {
                item.rect[0] = to_log(item.rect[0]);
                item.rect[1] = to_log(item.rect[1]);
            } else {
                to_log_space(item);
            }
        }
    }

    // ---- x range
    const Extent xe = x_extent(c.items, !fit_all);
    double x0 = link.x_min, x1 = link.x_max;
    if (fit_all) {
        x0 = xe.valid() ? xe.lo : 0.0;
        x1 = xe.valid() ? xe.hi : 1.0;
        pad(x0, x1, log ? 0.04 : 0.02);
    } else if (link.follow_latest) {
        const double first = xe.valid() ? xe.lo : 0.0, latest = xe.valid() ? xe.hi : 0.0;
        if (link.window_s > 0.0) {
            x0 = std::max(first, latest - link.window_s);
            x1 = x0 + link.window_s;
        } else {
            x0 = first;
            x1 = latest > first ? latest : first + 1.0;
        }
    }
    if (!(x1 > x0) || !std::isfinite(x0) || !std::isfinite(x1)) {
        x0 = 0.0;
        x1 = 1.0;
    }
    if (!fit_all) {
        link.x_min = x0;
        link.x_max = x1;
    }

    // ---- decimate the visible part of every line, and fit y to what shows
    const int columns = std::max(1, static_cast<int>(c.frame_size.x));
    Extent ye;
    for (Item& item : c.items) {
        item.points.clear();
        if (!item_visible(item)) continue;
        if (item.kind == ItemKind::line && item.count > 0) {
            if (fit_all) {
                for (int i = 0; i < item.count; ++i) item.points.push_back({plot_xs(item)[i], plot_ys(item)[i]});
            } else {
                decimate_m4(plot_xs(item), plot_ys(item), static_cast<std::size_t>(item.count), x0, x1, columns, item.points);
            }
            for (const PlotPoint& p : item.points)
                if (fit_all || (p.x >= x0 && p.x <= x1)) ye.add(p.y);
        } else if (item.kind == ItemKind::markers && item.ys) {
            for (int i = 0; i < item.count; ++i)
                if (fit_all || (plot_xs(item)[i] >= x0 && plot_xs(item)[i] <= x1)) ye.add(plot_ys(item)[i]);
        } else if (item.kind == ItemKind::rect && (fit_all || (item.rect[2] >= x0 && item.rect[0] <= x1))) {
            ye.add(item.rect[1]);
            ye.add(item.rect[3]);
        }
    }
    double y0 = st.y_min, y1 = st.y_max;
    if (fit_all || st.auto_fit_y) {
        y0 = ye.valid() ? ye.lo : 0.0;
        y1 = ye.valid() ? ye.hi : 1.0;
        pad(y0, y1, 0.06);
        st.y_min = y0;
        st.y_max = y1;
    }
    if (!(y1 > y0)) y1 = y0 + 1.0;

    // ---- legend entries (one per label), laid out once the plot area is known
    struct Entry {
        std::string label;
        ImU32 color;
        ImVec2 min, max;
    };
    std::vector<Entry> entries;
    if (!has_flag(PlotFlags_NoLegend)) {
        for (const Item& item : c.items) {
            // A band is named after its line, whose colour the swatch takes.
            if (item.legend.empty() || item.kind == ItemKind::text || item.kind == ItemKind::band) continue;
            if (std::none_of(entries.begin(), entries.end(), [&](const Entry& e) { return e.label == item.legend; }))
                entries.push_back({item.legend, item.color, {}, {}});
        }
    }
    const float swatch = line_h * 0.7f, row_h = line_h + 2.0f, padding = 4.0f;
    float entry_w = 0.0f;
    for (const Entry& e : entries) entry_w = std::max(entry_w, ImGui::CalcTextSize(e.label.c_str()).x);
    entry_w += swatch + 3 * padding;
    const bool legend_outside = has_flag(PlotFlags_LegendOutside) && !entries.empty();

    // ---- layout: header (y label, title), plot area, tick labels, x label
    const ImVec2 fmin = c.frame_min;
    const ImVec2 fmax{fmin.x + c.frame_size.x, fmin.y + c.frame_size.y};
    const bool header = !c.title.empty() || !c.y_label.empty();
    const float top = fmin.y + (header ? line_h + 4.0f : 4.0f);
    const float bottom = fmax.y - line_h - 6.0f - (has_flag(PlotFlags_NoXLabel) || c.x_label.empty() ? 0.0f : line_h + 2.0f);
    const AxisTicks yt = make_ticks(y0, y1, bottom - top, line_h * 2.2f, log);
    float label_w = 0.0f;
    for (const std::string& l : yt.labels) label_w = std::max(label_w, ImGui::CalcTextSize(l.c_str()).x);
    const float right = fmax.x - 6.0f - (legend_outside ? entry_w + 2 * padding : 0.0f);
    Frame f{x0, x1, y0, y1, {fmin.x + label_w + 8.0f, top}, {std::max(fmin.x + label_w + 20.0f, right), std::max(top + 10.0f, bottom)}};
    const AxisTicks xt = make_ticks(x0, x1, f.max.x - f.min.x, 90.0f, log);
    result.frame_min = fmin;
    result.frame_max = fmax;

    // ---- background, grid, ticks, labels
    dl->AddRectFilled(f.min, f.max, ImGui::GetColorU32(ImGuiCol_FrameBg));
    for (std::size_t i = 0; i < yt.at.size(); ++i) {
        const float y = f.py(yt.at[i]);
        dl->AddLine({f.min.x, y}, {f.max.x, y}, grid_col);
        const ImVec2 ts = ImGui::CalcTextSize(yt.labels[i].c_str());
        dl->AddText({f.min.x - 4.0f - ts.x, y - ts.y * 0.5f}, text_col, yt.labels[i].c_str());
    }
    float last_label_end = -1e9f;
    for (std::size_t i = 0; i < xt.at.size(); ++i) {
        const float x = f.px(xt.at[i]);
        dl->AddLine({x, f.min.y}, {x, f.max.y}, grid_col);
        const ImVec2 ts = ImGui::CalcTextSize(xt.labels[i].c_str());
        const float lx = std::clamp(x - ts.x * 0.5f, fmin.x, fmax.x - ts.x);
        if (lx < last_label_end + 6.0f) continue;  // never let labels collide
        dl->AddText({lx, f.max.y + 3.0f}, text_col, xt.labels[i].c_str());
        last_label_end = lx + ts.x;
    }
    if (!c.y_label.empty()) dl->AddText({fmin.x, fmin.y}, text_col, c.y_label.c_str());
    if (!c.title.empty()) {
        const float tw = ImGui::CalcTextSize(c.title.c_str()).x;
        dl->AddText({std::max(fmin.x + ImGui::CalcTextSize(c.y_label.c_str()).x + 16.0f, (f.min.x + f.max.x - tw) * 0.5f), fmin.y},
                    text_col, c.title.c_str());
    }
    if (!has_flag(PlotFlags_NoXLabel) && !c.x_label.empty()) {
        const float tw = ImGui::CalcTextSize(c.x_label.c_str()).x;
        dl->AddText({(f.min.x + f.max.x - tw) * 0.5f, f.max.y + line_h + 5.0f}, text_col, c.x_label.c_str());
    }

    // ---- data
    dl->PushClipRect(f.min, f.max, true);
    for (const Item& item : c.items) {
        if (item.kind == ItemKind::rect && item_visible(item))
            dl->AddRectFilled({f.px(item.rect[0]), f.py(item.rect[3])}, {f.px(item.rect[2]), f.py(item.rect[1])}, item.color);
        if (item.kind == ItemKind::band && item_visible(item) && !log) draw_band(dl, f, item);
    }
    for (const Item& item : c.items) {
        if (!item_visible(item)) continue;
        if (item.kind == ItemKind::line) {
            draw_polyline(dl, f, item.points, item.color, item.thickness);
        } else if (item.kind == ItemKind::markers) {
            const double* xs = plot_xs(item);
            const double* ys = plot_ys(item);
            for (int i = 0; i < item.count; ++i) {
                if (!(xs[i] >= x0 && xs[i] <= x1)) continue;
                if (ys) {
                    if (std::isfinite(ys[i])) draw_marker(dl, {f.px(xs[i]), f.py(ys[i])}, item.shape, item.size, item.color);
                } else {
                    const float x = f.px(xs[i]);
                    dl->AddLine({x, f.max.y}, {x, f.max.y - 2.0f * item.size}, item.color, 1.5f);
                }
            }
        } else if (item.kind == ItemKind::text && std::isfinite(item.rect[0]) && std::isfinite(item.rect[1])) {
            dl->AddText({f.px(item.rect[0]) + 6.0f, f.py(item.rect[1]) - line_h - 2.0f}, item.color, item.text.c_str());
        }
    }
    if (!fit_all && std::isfinite(link.hover_x) && link.hover_x >= x0 && link.hover_x <= x1) {
        const float x = f.px(link.hover_x);
        dl->AddLine({x, f.min.y}, {x, f.max.y}, dim_col);
    }
    dl->PopClipRect();
    dl->AddRect(f.min, f.max, ImGui::GetColorU32(ImGuiCol_Border));

    // ---- legend: top right inside the plot (in columns when tall), or beside it
    if (!entries.empty()) {
        const float avail_h = legend_outside ? fmax.y - f.min.y : f.max.y - f.min.y - 2 * padding;
        const int rows_fit = std::max(1, static_cast<int>(avail_h / row_h));
        const int cols = (static_cast<int>(entries.size()) + rows_fit - 1) / rows_fit;
        const int rows = (static_cast<int>(entries.size()) + cols - 1) / cols;
        const float box_right = legend_outside ? fmax.x - 2.0f : f.max.x - padding;
        const ImVec2 box_max{box_right, f.min.y + (legend_outside ? 0.0f : padding) + rows * row_h + 2 * padding};
        const ImVec2 box_min{box_max.x - cols * entry_w - padding, f.min.y + (legend_outside ? 0.0f : padding)};
        dl->AddRectFilled(box_min, box_max, ImGui::GetColorU32(ImGuiCol_WindowBg, 0.8f), 3.0f);
        for (std::size_t i = 0; i < entries.size(); ++i) {
            Entry& e = entries[i];
            const int col = static_cast<int>(i) / rows, row = static_cast<int>(i) % rows;
            e.min = {box_min.x + padding + col * entry_w, box_min.y + padding + row * row_h};
            e.max = {e.min.x + entry_w, e.min.y + row_h};
            const bool hidden = c.hidden->count(e.label) > 0;
            const ImVec2 sw_min{e.min.x, e.min.y + (row_h - swatch) * 0.5f};
            const ImVec2 sw_max{sw_min.x + swatch, sw_min.y + swatch};
            if (hidden) dl->AddRect(sw_min, sw_max, e.color);
            else dl->AddRectFilled(sw_min, sw_max, e.color);
            dl->AddText({sw_max.x + padding, e.min.y + 1.0f}, hidden ? dim_col : text_col, e.label.c_str());
        }
    }

    // ---- interaction
    ImGui::SetCursorScreenPos(f.min);
    ImGui::InvisibleButton("##area", {std::max(1.0f, f.max.x - f.min.x), std::max(1.0f, f.max.y - f.min.y)},
                           ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight);
    const bool hovered = ImGui::IsItemHovered();
    const bool active = ImGui::IsItemActive();
    result.hovered = hovered;
    const ImVec2 mouse = io.MousePos;
    const Entry* over_entry = nullptr;
    for (const Entry& e : entries)
        if (mouse.x >= e.min.x && mouse.x < e.max.x && mouse.y >= e.min.y && mouse.y < e.max.y) over_entry = &e;
    const bool legend_clickable = hovered || (legend_outside && ImGui::IsWindowHovered());
    if (legend_clickable && over_entry && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
        if (c.hidden->erase(over_entry->label) == 0) c.hidden->insert(over_entry->label);
    } else if (hovered && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) {
        link.follow_latest = true;
        st.auto_fit_y = true;
    } else if (!fit_all && active && ImGui::IsMouseDragging(ImGuiMouseButton_Left) && !over_entry) {
        const double dx = io.MouseDelta.x * (x1 - x0) / (f.max.x - f.min.x);
        if (dx != 0.0) {
            link.follow_latest = false;
            link.x_min -= dx;
            link.x_max -= dx;
        }
        if (!st.auto_fit_y) {
            const double dy = io.MouseDelta.y * (y1 - y0) / (f.max.y - f.min.y);
            st.y_min += dy;
            st.y_max += dy;
        }
    }
    if (!fit_all && hovered && io.MouseWheel != 0.0f) {
        const double factor = std::pow(0.8, static_cast<double>(io.MouseWheel));
        if (io.KeyCtrl) {
            const double my = f.data_y(mouse.y);
            st.auto_fit_y = false;
            st.y_min = my + (y0 - my) * factor;
            st.y_max = my + (y1 - my) * factor;
        } else if (link.follow_latest) {
            link.window_s = std::clamp((link.window_s > 0.0 ? link.window_s : x1 - x0) * factor, 1e-3, 1e7);
        } else {
            const double mx = f.data_x(mouse.x);
            link.x_min = mx + (x0 - mx) * factor;
            link.x_max = mx + (x1 - mx) * factor;
        }
    }
    if (hovered && ImGui::IsMouseReleased(ImGuiMouseButton_Right) && ImGui::GetMouseDragDelta(ImGuiMouseButton_Right).x == 0.0f)
        ImGui::OpenPopup("##plot_menu");

    // ---- hover readout of the nearest sample
    const bool readout = hovered && !has_flag(PlotFlags_NoHover);
    if (!fit_all) link.hover_x = readout ? f.data_x(mouse.x) : (link.hover_owner == c.id || has_flag(PlotFlags_NoHover) ? nan : link.hover_x);
    if (readout) link.hover_owner = c.id;
    if (readout && !over_entry && !ImGui::IsMouseDragging(ImGuiMouseButton_Left)) {
        const Nearest n = find_nearest(c.items, f, mouse, !fit_all);
        if (n.item && n.distance < 60.0f) {
            dl->AddCircle(n.at, 5.0f, text_col, 12, 1.5f);
            ImGui::BeginTooltip();
            if (!n.item->legend.empty()) ImGui::TextUnformatted(n.item->legend.c_str());
            ImGui::Text("%s: %.6g", c.x_label.empty() ? "x" : c.x_label.c_str(), n.x);
            ImGui::Text("%s: %.6g", c.y_label.empty() ? "y" : c.y_label.c_str(), n.y);
            ImGui::EndTooltip();
        }
    }

    // ---- context menu
    if (ImGui::BeginPopup("##plot_menu")) {
        if (!fit_all) {
            ImGui::MenuItem("Follow latest", nullptr, &link.follow_latest);
            ImGui::MenuItem("Auto-fit y", nullptr, &st.auto_fit_y);
            if (ImGui::MenuItem("Show all data")) {
                link.follow_latest = true;
                link.window_s = 0.0;
                st.auto_fit_y = true;
            }
            ImGui::Separator();
        }
        if (ImGui::MenuItem("Export visible data to CSV")) result.export_csv = true;
        if (ImGui::MenuItem("Export plot to PNG")) result.export_png = true;
        ImGui::EndPopup();
    }
    if (has_flag(PlotFlags_ExportCsv)) result.export_csv = true;
    if (result.export_csv) result.csv = visible_csv(c, x0, x1, log);

    // The whole widget is one layout item.
    ImGui::SetCursorScreenPos(fmin);
    ImGui::Dummy(c.frame_size);
    ImGui::PopID();
    c.items.clear();
    c.active = false;
    return result;
}

}  // namespace pl::ui::plot
