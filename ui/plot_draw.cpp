// The plot widget's drawing: axis ranges and ticks, grid and labels, the items, the legend.
#include "ui/plot_internal.hpp"

#include <cstdio>
#include <utility>

namespace pl::ui::plot::detail {

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

void mark_coincident(std::vector<Item>& items, double y_per_pixel) {
    for (std::size_t j = 0; j < items.size(); ++j) {
        Item& later = items[j];
        later.coincides_with.clear();
        later.dash_style = 0;
        if (later.kind != ItemKind::line || !item_visible(later) || later.legend.empty()) continue;
        for (std::size_t i = 0; i < j; ++i) {
            const Item& earlier = items[i];
            if (earlier.kind != ItemKind::line || !item_visible(earlier) || earlier.legend.empty() ||
                earlier.legend == later.legend || !coincide(earlier.points, later.points, y_per_pixel))
                continue;
            // Named after the first line of the group; each further one gets the next pattern.
            later.coincides_with = earlier.coincides_with.empty() ? earlier.legend : earlier.coincides_with;
            later.dash_style = earlier.dash_style + 1;
        }
    }
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

namespace {

std::string log_label(double v) {
    char buf[32];
    if (v >= 1e-3 && v < 1e4) std::snprintf(buf, sizeof buf, "%g", v);
    else std::snprintf(buf, sizeof buf, "%.0e", v);
    return buf;
}

}  // namespace

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
    TickLabels labels = label_ticks(ticks);
    t.at = ticks.values;
    t.labels = std::move(labels.labels);
    t.offset = std::move(labels.offset);
    return t;
}

namespace {

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

// A run of points as dashes of `on` pixels with `off` pixel gaps, the pattern carried across
// the run's segments so the dashes keep their length however finely the line is sampled.
void draw_dashed(ImDrawList* dl, const std::vector<ImVec2>& run, ImU32 col, float thickness, float on, float off) {
    float phase = 0.0f;  // position within the current on+off period
    for (std::size_t k = 0; k + 1 < run.size(); ++k) {
        const ImVec2 a = run[k], b = run[k + 1];
        const float length = std::hypot(b.x - a.x, b.y - a.y);
        float done = 0.0f;
        while (done < length) {
            const bool drawing = phase < on;
            const float step = std::min(length - done, drawing ? on - phase : on + off - phase);
            if (drawing && length > 0.0f) {
                const float t0 = done / length, t1 = (done + step) / length;
                dl->AddLine({a.x + (b.x - a.x) * t0, a.y + (b.y - a.y) * t0}, {a.x + (b.x - a.x) * t1, a.y + (b.y - a.y) * t1}, col,
                            thickness);
            }
            done += step;
            phase += step;
            if (phase >= on + off) phase = 0.0f;
        }
    }
}

// Dash patterns (on, off) in pixels for the 1st, 2nd, ... line that coincides with another.
constexpr float dash_patterns[][2] = {{7.0f, 5.0f}, {2.0f, 4.0f}, {12.0f, 4.0f}, {4.0f, 9.0f}};

void draw_polyline(ImDrawList* dl, const Frame& f, const std::vector<PlotPoint>& points, ImU32 col, float thickness,
                   int dash_style = 0) {
    static std::vector<ImVec2> run;
    auto flush = [&] {
        if (run.size() >= 2 && dash_style > 0) {
            const float* pattern = dash_patterns[static_cast<std::size_t>(dash_style - 1) % std::size(dash_patterns)];
            draw_dashed(dl, run, col, thickness + 0.5f, pattern[0], pattern[1]);
        } else if (run.size() >= 2) {
            dl->AddPolyline(run.data(), static_cast<int>(run.size()), col, ImDrawFlags_None, thickness);
        } else if (run.size() == 1) {
            dl->AddCircleFilled(run[0], thickness, col, 6);
        }
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


}  // namespace

void draw_axes(ImDrawList* dl, const Context& c, const PlotLayout& l, const AxisTicks& xt, const AxisTicks& yt,
               const Style& s) {
    const Frame& f = l.frame;
    const ImVec2 fmin = l.widget_min, fmax = l.widget_max;
    dl->AddRectFilled(f.min, f.max, ImGui::GetColorU32(ImGuiCol_FrameBg));
    for (std::size_t i = 0; i < yt.at.size(); ++i) {
        const float y = f.py(yt.at[i]);
        dl->AddLine({f.min.x, y}, {f.max.x, y}, s.grid);
        const ImVec2 ts = ImGui::CalcTextSize(yt.labels[i].c_str());
        dl->AddText({f.min.x - 4.0f - ts.x, y - ts.y * 0.5f}, s.text, yt.labels[i].c_str());
    }
    float last_label_end = -1e9f;
    for (std::size_t i = 0; i < xt.at.size(); ++i) {
        const float x = f.px(xt.at[i]);
        dl->AddLine({x, f.min.y}, {x, f.max.y}, s.grid);
        const ImVec2 ts = ImGui::CalcTextSize(xt.labels[i].c_str());
        const float lx = std::clamp(x - ts.x * 0.5f, fmin.x, fmax.x - ts.x);
        if (lx < last_label_end + 6.0f) continue;  // never let labels collide
        dl->AddText({lx, f.max.y + 3.0f}, s.text, xt.labels[i].c_str());
        last_label_end = lx + ts.x;
    }
    if (!c.y_label.empty()) dl->AddText({fmin.x, fmin.y}, s.text, c.y_label.c_str());
    if (!c.title.empty()) {
        const float tw = ImGui::CalcTextSize(c.title.c_str()).x;
        dl->AddText({std::max(fmin.x + ImGui::CalcTextSize(c.y_label.c_str()).x + 16.0f, (f.min.x + f.max.x - tw) * 0.5f), fmin.y},
                    s.text, c.title.c_str());
    }
    if (!has_flag(PlotFlags_NoXLabel) && !c.x_label.empty()) {
        const float tw = ImGui::CalcTextSize(c.x_label.c_str()).x;
        dl->AddText({(f.min.x + f.max.x - tw) * 0.5f, f.max.y + s.line_h + 5.0f}, s.text, c.x_label.c_str());
    }
    // The offsets the labels add to (plot_math.hpp, label_ticks): the y axis's at the header's
    // right end, the x axis's at the right end of the x label's row.
    if (!yt.offset.empty())
        dl->AddText({f.max.x - ImGui::CalcTextSize(yt.offset.c_str()).x, fmin.y}, s.text, yt.offset.c_str());
    if (!xt.offset.empty())
        dl->AddText({f.max.x - ImGui::CalcTextSize(xt.offset.c_str()).x, f.max.y + s.line_h + 5.0f}, s.text,
                    xt.offset.c_str());
}

namespace {

void draw_markers(ImDrawList* dl, const Frame& f, const Item& item) {
    const double* xs = plot_xs(item);
    const double* ys = plot_ys(item);
    for (int i = 0; i < item.count; ++i) {
        if (!(xs[i] >= f.x0 && xs[i] <= f.x1)) continue;
        if (ys) {
            if (std::isfinite(ys[i])) draw_marker(dl, {f.px(xs[i]), f.py(ys[i])}, item.shape, item.size, item.color);
        } else {
            const float x = f.px(xs[i]);
            dl->AddLine({x, f.max.y}, {x, f.max.y - 2.0f * item.size}, item.color, 1.5f);
        }
    }
}

// Samples <= 0 have no place on a log axis: a small triangle standing on the x axis marks each
// (an error of exactly 0 is a result, not a missing point).
void draw_log_zeros(ImDrawList* dl, const Frame& f, const Item& item) {
    const float r = 4.0f;
    for (int i = 0; i < item.count; ++i) {
        if (!(item.ys[i] <= 0.0)) continue;
        const double x = plot_xs(item)[i];
        if (!(x >= f.x0 && x <= f.x1)) continue;
        const float px = f.px(x), base = f.max.y - 1.0f;
        dl->AddTriangleFilled({px - r, base}, {px + r, base}, {px, base - 1.7f * r}, item.color);
    }
}

}  // namespace

void draw_items(ImDrawList* dl, const Context& c, const Frame& f, bool log, const Style& s) {
    const bool fit_all = log || has_flag(PlotFlags_FitAll);
    dl->PushClipRect(f.min, f.max, true);
    // Areas first, beneath every line.
    for (const Item& item : c.items) {
        if (item.kind == ItemKind::rect && item_visible(item))
            dl->AddRectFilled({f.px(item.rect[0]), f.py(item.rect[3])}, {f.px(item.rect[2]), f.py(item.rect[1])}, item.color);
        if (item.kind == ItemKind::band && item_visible(item) && !log) draw_band(dl, f, item);
    }
    for (const Item& item : c.items) {
        if (!item_visible(item)) continue;
        if (item.zeros_on_log > 0) draw_log_zeros(dl, f, item);
        if (item.kind == ItemKind::line) {
            draw_polyline(dl, f, item.points, item.color, item.thickness, item.dash_style);
        } else if (item.kind == ItemKind::markers) {
            draw_markers(dl, f, item);
        } else if (item.kind == ItemKind::text && std::isfinite(item.rect[0]) && std::isfinite(item.rect[1])) {
            dl->AddText({f.px(item.rect[0]) + 6.0f, f.py(item.rect[1]) - s.line_h - 2.0f}, item.color, item.text.c_str());
        }
    }
    const TimeAxisLink& link = *c.x;
    if (!fit_all && std::isfinite(link.hover_x) && link.hover_x >= f.x0 && link.hover_x <= f.x1) {
        const float x = f.px(link.hover_x);
        dl->AddLine({x, f.min.y}, {x, f.max.y}, s.dim);
    }
    dl->PopClipRect();
    dl->AddRect(f.min, f.max, ImGui::GetColorU32(ImGuiCol_Border));
}

// Top right inside the plot (in columns when tall), or beside it.
void draw_legend(ImDrawList* dl, const Context& c, const PlotLayout& l, std::vector<LegendEntry>& entries,
                 const Style& s) {
    if (entries.empty()) return;
    const Frame& f = l.frame;
    const float swatch = s.line_h * 0.7f, row_h = s.line_h + 2.0f, padding = 4.0f;
    const float avail_h = l.legend_outside ? l.widget_max.y - f.min.y : f.max.y - f.min.y - 2 * padding;
    const int rows_fit = std::max(1, static_cast<int>(avail_h / row_h));
    const int cols = (static_cast<int>(entries.size()) + rows_fit - 1) / rows_fit;
    const int rows = (static_cast<int>(entries.size()) + cols - 1) / cols;
    const float box_right = l.legend_outside ? l.widget_max.x - 2.0f : f.max.x - padding;
    const ImVec2 box_max{box_right, f.min.y + (l.legend_outside ? 0.0f : padding) + rows * row_h + 2 * padding};
    const ImVec2 box_min{box_max.x - cols * l.entry_w - padding, f.min.y + (l.legend_outside ? 0.0f : padding)};
    dl->AddRectFilled(box_min, box_max, ImGui::GetColorU32(ImGuiCol_WindowBg, 0.8f), 3.0f);
    for (std::size_t i = 0; i < entries.size(); ++i) {
        LegendEntry& e = entries[i];
        const int col = static_cast<int>(i) / rows, row = static_cast<int>(i) % rows;
        e.min = {box_min.x + padding + col * l.entry_w, box_min.y + padding + row * row_h};
        e.max = {e.min.x + l.entry_w, e.min.y + row_h};
        const bool hidden = c.hidden->count(e.label) > 0;
        const ImVec2 sw_min{e.min.x, e.min.y + (row_h - swatch) * 0.5f};
        const ImVec2 sw_max{sw_min.x + swatch, sw_min.y + swatch};
        if (hidden) dl->AddRect(sw_min, sw_max, e.color);
        else dl->AddRectFilled(sw_min, sw_max, e.color);
        dl->AddText({sw_max.x + padding, e.min.y + 1.0f}, hidden ? s.dim : s.text, e.label.c_str());
        if (!e.note.empty())
            dl->AddText({sw_max.x + padding + ImGui::CalcTextSize((e.label + " ").c_str()).x, e.min.y + 1.0f}, s.dim,
                        e.note.c_str());
    }
}

}  // namespace pl::ui::plot::detail
