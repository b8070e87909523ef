// The plot widget's API (ui/plot.hpp): BeginPlot collects items, EndPlot lays out, draws and
// handles input in phases (plot_draw.cpp, plot_interact.cpp).
#include "ui/plot_internal.hpp"

#include <cstring>

namespace pl::ui::plot {

namespace detail {

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
        item.zeros_on_log = 0;
        for (int i = 0; i < item.count; ++i) {
            item.log_ys[static_cast<std::size_t>(i)] = to_log(item.ys[i]);
            if (item.ys[i] <= 0.0 && item.xs[i] > 0.0) ++item.zeros_on_log;  // e.g. an exact error of 0
        }
    }
}

const double* plot_xs(const Item& i) { return i.log_xs.empty() ? i.xs : i.log_xs.data(); }
const double* plot_ys(const Item& i) { return i.log_ys.empty() ? i.ys : i.log_ys.data(); }

}  // namespace detail

using namespace detail;

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

void SetItemDetail(std::function<std::string(double x)> detail) {
    if (!context().items.empty()) context().items.back().detail = std::move(detail);
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


namespace {

using namespace detail;

// The x range: everything (fit_all), the newest window (following), or where the user left it.
void x_range(Context& c, bool fit_all, bool log, double& x0, double& x1) {
    TimeAxisLink& link = *c.x;
    const Extent xe = x_extent(c.items, !fit_all);
    x0 = link.x_min;
    x1 = link.x_max;
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
}

// Decimates the visible part of every line and fits y to what shows (unless the user set y).
void y_range(Context& c, bool fit_all, double x0, double x1, double& y0, double& y1) {
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
    PlotState& st = *c.state;
    y0 = st.y_min;
    y1 = st.y_max;
    if (fit_all || st.auto_fit_y) {
        y0 = ye.valid() ? ye.lo : 0.0;
        y1 = ye.valid() ? ye.hi : 1.0;
        if (!has_flag(PlotFlags_LogLog)) constant_range(y0, y1);
        pad(y0, y1, 0.06);
        st.y_min = y0;
        st.y_max = y1;
    }
    if (!(y1 > y0)) y1 = y0 + 1.0;
}

// One entry per label; a band is named after its line, whose colour the swatch takes.
std::vector<LegendEntry> legend_entries(const Context& c) {
    std::vector<LegendEntry> entries;
    if (has_flag(PlotFlags_NoLegend)) return entries;
    for (const Item& item : c.items) {
        if (item.legend.empty() || item.kind == ItemKind::text || item.kind == ItemKind::band) continue;
        if (std::none_of(entries.begin(), entries.end(), [&](const LegendEntry& e) { return e.label == item.legend; })) {
            std::string note;
            if (!item.coincides_with.empty()) note = "(dashed: on " + item.coincides_with + ")";
            if (item.zeros_on_log > 0) note += std::string(note.empty() ? "" : " ") + "(zeros: marks on the x axis)";
            entries.push_back({item.legend, note, item.color, {}, {}});
        }
    }
    return entries;
}

// Header (y label, title), plot area, tick labels, x label; the y ticks decide the left margin.
PlotLayout layout(const Context& c, const std::vector<LegendEntry>& entries, double x0, double x1, double y0,
                  double y1, bool log, float line_h, AxisTicks& yt) {
    PlotLayout l;
    const float swatch = line_h * 0.7f, padding = 4.0f;
    for (const LegendEntry& e : entries)
        l.entry_w = std::max(l.entry_w, ImGui::CalcTextSize((e.label + (e.note.empty() ? "" : " " + e.note)).c_str()).x);
    l.entry_w += swatch + 3 * padding;
    l.legend_outside = has_flag(PlotFlags_LegendOutside) && !entries.empty();
    l.widget_min = c.frame_min;
    l.widget_max = {c.frame_min.x + c.frame_size.x, c.frame_min.y + c.frame_size.y};
    const ImVec2 fmin = l.widget_min, fmax = l.widget_max;
    const bool header = !c.title.empty() || !c.y_label.empty();
    const float top = fmin.y + (header ? line_h + 4.0f : 4.0f);
    const float bottom = fmax.y - line_h - 6.0f - (has_flag(PlotFlags_NoXLabel) || c.x_label.empty() ? 0.0f : line_h + 2.0f);
    yt = make_ticks(y0, y1, bottom - top, line_h * 2.2f, log);
    float label_w = 0.0f;
    for (const std::string& s : yt.labels) label_w = std::max(label_w, ImGui::CalcTextSize(s.c_str()).x);
    const float right = fmax.x - 6.0f - (l.legend_outside ? l.entry_w + 2 * padding : 0.0f);
    l.frame = Frame{x0, x1, y0, y1, {fmin.x + label_w + 8.0f, top}, {std::max(fmin.x + label_w + 20.0f, right), std::max(top + 10.0f, bottom)}};
    return l;
}

}  // namespace

PlotResult EndPlot() {
    Context& c = context();
    IM_ASSERT(c.active && "EndPlot without BeginPlot");
    const bool log = has_flag(PlotFlags_LogLog);
    const bool fit_all = log || has_flag(PlotFlags_FitAll);
    const Style style{ImGui::GetTextLineHeight(), ImGui::GetColorU32(ImGuiCol_Text),
                      ImGui::GetColorU32(ImGuiCol_TextDisabled), ImGui::GetColorU32(ImGuiCol_TextDisabled, 0.22f)};
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
    double x0 = 0.0, x1 = 1.0, y0 = 0.0, y1 = 1.0;
    x_range(c, fit_all, log, x0, x1);
    y_range(c, fit_all, x0, x1, y0, y1);
    // Within a line's width (1.5 px) a curve is hidden under the one drawn over it.
    mark_coincident(c.items, 1.5 * (y1 - y0) / std::max(1.0f, c.frame_size.y));
    std::vector<LegendEntry> entries = legend_entries(c);
    AxisTicks yt;
    const PlotLayout l = layout(c, entries, x0, x1, y0, y1, log, style.line_h, yt);
    const Frame& f = l.frame;
    const AxisTicks xt = make_ticks(x0, x1, f.max.x - f.min.x, 90.0f, log);

    ImDrawList* dl = ImGui::GetWindowDrawList();
    draw_axes(dl, c, l, xt, yt, style);
    draw_items(dl, c, f, log, style);
    draw_legend(dl, c, l, entries, style);

    PlotResult result;
    result.frame_min = l.widget_min;
    result.frame_max = l.widget_max;
    const LegendEntry* over_entry = interact(c, f, entries, l.legend_outside, fit_all, result);
    result.x_min = f.x0, result.x_max = f.x1, result.y_min = f.y0, result.y_max = f.y1;
    result.area_min = f.min, result.area_max = f.max;
    const ImVec2 mouse = ImGui::GetIO().MousePos;
    const bool on_area = mouse.x >= f.min.x && mouse.x <= f.max.x && mouse.y >= f.min.y && mouse.y <= f.max.y;
    if (result.hovered && on_area && !over_entry && ImGui::IsMouseReleased(ImGuiMouseButton_Left) &&
        ImGui::GetIO().MouseDragMaxDistanceSqr[ImGuiMouseButton_Left] < 16.0f) {
        result.clicked = true;
        result.click_x = f.data_x(mouse.x);
        result.click_y = f.data_y(mouse.y);
    }
    hover_readout(c, f, over_entry, fit_all, result.hovered, style);
    context_menu(c, fit_all, result);
    if (has_flag(PlotFlags_ExportCsv)) result.export_csv = true;
    if (result.export_csv) result.csv = visible_csv(c, x0, x1, log);

    // The whole widget is one layout item.
    ImGui::SetCursorScreenPos(l.widget_min);
    ImGui::Dummy(c.frame_size);
    ImGui::PopID();
    c.items.clear();
    c.active = false;
    return result;
}

}  // namespace pl::ui::plot
