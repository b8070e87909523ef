// The plot widget's pure math: "nice" axis ticks and per-pixel-column decimation. No ImGui, so
// the unit tests include it directly.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

namespace pl::ui {

// A step of 1, 2 or 5 times a power of ten that cuts `span` into about `target` intervals
// (Heckbert, "Nice numbers for graph labels", Graphics Gems, 1990). 0 for an empty span.
inline double nice_step(double span, int target) {
    if (!(span > 0.0) || !std::isfinite(span) || target < 1) return 0.0;
    const double raw = span / target;
    const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
    const double fraction = raw / magnitude;  // in [1, 10)
    const double mantissa = fraction < 1.5 ? 1.0 : fraction < 3.5 ? 2.0 : fraction < 7.5 ? 5.0 : 10.0;
    return mantissa * magnitude;
}

struct Ticks {
    std::vector<double> values;  // ascending, every one inside [lo, hi]
    double step = 0.0;
};

// Multiples of nice_step(hi - lo, target) inside [lo, hi]. Each value is k * step (not a running
// sum, which would accumulate rounding), and values within rounding of zero are exactly 0.
inline Ticks nice_ticks(double lo, double hi, int target) {
    Ticks ticks;
    if (!(hi > lo)) return ticks;
    ticks.step = nice_step(hi - lo, target);
    if (ticks.step == 0.0) return ticks;
    const double slack = 1e-9;  // admit a tick that sits on an end up to rounding
    const double first = std::ceil(lo / ticks.step - slack);
    const double last = std::floor(hi / ticks.step + slack);
    if (last - first > 1000.0) return ticks;  // cannot happen for a sane target; stay bounded
    for (double k = first; k <= last; k += 1.0) {
        const double v = k * ticks.step;
        ticks.values.push_back(std::abs(v) < ticks.step * slack ? 0.0 : v);
    }
    return ticks;
}

// Powers of ten inside [lo, hi] (lo > 0), plus 2x and 5x when fewer than three decades show.
inline Ticks log_ticks(double lo, double hi) {
    Ticks ticks;
    if (!(lo > 0.0) || !(hi > lo) || !std::isfinite(hi)) return ticks;
    const int first = static_cast<int>(std::floor(std::log10(lo)));
    const int last = static_cast<int>(std::ceil(std::log10(hi)));
    const bool fine = last - first < 3;
    for (int e = first; e <= last && ticks.values.size() < 200; ++e) {
        const double decade = std::pow(10.0, e);
        for (double m : {1.0, 2.0, 5.0}) {
            if (m != 1.0 && !fine) continue;
            const double v = m * decade;
            if (v >= lo * (1 - 1e-12) && v <= hi * (1 + 1e-12)) ticks.values.push_back(v);
        }
    }
    ticks.step = 10.0;
    return ticks;
}

// The power of ten of a tick step (0 for no step): 2e-12 -> -12, 5 -> 0, 20 -> 1.
inline int decade_of(double step) {
    return step > 0.0 ? static_cast<int>(std::floor(std::log10(step) + 1e-9)) : 0;
}

// A tick label with just enough digits to tell neighbouring ticks `step` apart: fixed notation
// for ordinary magnitudes (however fine the step: 87.4694012 J on an axis that spans round-off),
// scientific for very small or very large values. Digits stop where a double has none left.
inline std::string format_tick(double value, double step) {
    char buf[48];
    if (value == 0.0) return "0";
    const double mag = std::abs(value);
    const int step_exponent = decade_of(step);
    if (step > 0.0 && mag < 1e6 && (step >= 1e-4 || mag >= 1e-3)) {
        const int decimals = std::clamp(-step_exponent, 0, 15);
        std::snprintf(buf, sizeof buf, "%.*f", decimals, value);
    } else {
        // Digits after the point in the mantissa: as many as the step needs relative to the value.
        int digits = 0;
        if (step > 0.0) digits = std::clamp(static_cast<int>(std::floor(std::log10(mag))) - step_exponent, 0, 16);
        std::snprintf(buf, sizeof buf, "%.*e", digits, value);
    }
    return buf;
}

// The labels of a linear axis. Where they would need more than `most_digits` significant digits
// (an axis that spans round-off around a large value: an elastic gas's energy, 87.4694012340 J
// +- 1e-11), they read as an offset plus short labels of what each tick adds to it, as
// matplotlib's ScalarFormatter does ("+87.469401234" at the axis, ticks "0", "2e-12", "4e-12").
// The offset is the first tick rounded down to a multiple of 100 steps' decade, so the labels
// keep about three digits and a scrolling axis changes its offset rarely.
struct TickLabels {
    std::vector<std::string> labels;  // one per tick
    std::string offset;               // empty: the labels are the values themselves
};
inline TickLabels label_ticks(const Ticks& ticks, int most_digits = 7) {
    TickLabels out;
    if (ticks.values.empty()) return out;
    const double step = ticks.step;
    double largest = 0.0;
    for (const double v : ticks.values) largest = std::max(largest, std::abs(v));
    const int step_exponent = decade_of(step);
    const bool offset = step > 0.0 && largest > 0.0 &&
                        static_cast<int>(std::floor(std::log10(largest))) - step_exponent >= most_digits;
    if (!offset) {
        for (const double v : ticks.values) out.labels.push_back(format_tick(v, step));
        return out;
    }
    const int exponent = step_exponent + 2;
    const double unit = std::pow(10.0, exponent);
    const double base = std::floor(ticks.values.front() / unit) * unit;
    for (const double v : ticks.values) out.labels.push_back(format_tick(v - base, step));
    // The offset with the digits of its own step, signed: "+87.4694012340".
    char buf[64];
    std::snprintf(buf, sizeof buf, "%s%s", base < 0.0 ? "" : "+", format_tick(base, unit).c_str());
    out.offset = buf;
    return out;
}

// The y range of data that never changes (lo == hi): the span from zero to the value, so a ball
// at rest at 0.033 m reads "0 .. 0.04" and not five labels of 0.033, and an exact zero gets
// [-1, 1] rather than +-1e-9 of rounding noise. Varying data (lo < hi) is left as it is.
inline void constant_range(double& lo, double& hi) {
    if (!(lo == hi) || !std::isfinite(lo)) return;
    if (lo == 0.0) {
        lo = -1.0;
        hi = 1.0;
        return;
    }
    const double v = lo;
    lo = std::min(0.0, v);
    hi = std::max(0.0, v);
}

// Whether a decimated line `b` draws (nearly) on the pixels of line `a`: at each of b's points,
// a interpolated linearly at that x (both ascending in x; the lines' sample times may differ,
// e.g. at bounces) is within `tolerance` (data units, about a line's width), at all but
// `allowed_off` of the points: a curve hidden under another for most of its length hides just
// as well as one hidden all along. A point outside a's span or at a gap counts as off.
template <class Point>
bool coincide(const std::vector<Point>& a, const std::vector<Point>& b, double tolerance, double allowed_off = 0.1) {
    if (a.size() < 2 || b.empty()) return false;
    std::size_t off = 0, k = 0;
    const auto budget = static_cast<std::size_t>(allowed_off * static_cast<double>(b.size()));
    for (const Point& p : b) {
        while (k + 2 < a.size() && a[k + 1].x < p.x) ++k;
        const Point &lo = a[k], &hi = a[k + 1];
        bool near = false;
        if (p.x >= lo.x && p.x <= hi.x && std::isfinite(lo.y) && std::isfinite(hi.y)) {
            const double y = hi.x > lo.x ? lo.y + (hi.y - lo.y) * (p.x - lo.x) / (hi.x - lo.x) : lo.y;
            near = std::isfinite(p.y) && std::abs(p.y - y) <= tolerance;
            // Where a jumps (two samples at one time, a bounce), either side will do.
            near = near || (hi.x == lo.x && std::isfinite(p.y) && std::abs(p.y - hi.y) <= tolerance);
        }
        if (!near && ++off > budget) return false;
    }
    return true;
}

struct PlotPoint {
    double x, y;  // y is NaN at a gap (a non-finite sample): the line breaks there
};

// Reduces the samples with x in [x_lo, x_hi] (xs ascending), plus one neighbour on each side so
// the line reaches the plot's edges, to at most four points per pixel column: the column's
// first, lowest, highest and last sample in time order (the "M4" aggregation of Jugel et al.,
// VLDB 2014). A line through them rasterises like a line through every sample, but costs
// O(columns) to draw however many samples there are; extremes are never lost.
inline void decimate_m4(const double* xs, const double* ys, std::size_t n, double x_lo, double x_hi, int columns,
                        std::vector<PlotPoint>& out) {
    out.clear();
    if (n == 0 || !(x_hi > x_lo) || columns < 1) return;
    std::size_t begin = static_cast<std::size_t>(std::lower_bound(xs, xs + n, x_lo) - xs);
    std::size_t end = static_cast<std::size_t>(std::upper_bound(xs, xs + n, x_hi) - xs);
    if (begin > 0) --begin;
    if (end < n) ++end;
    if (begin >= end) return;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    if (end - begin <= static_cast<std::size_t>(4 * columns)) {
        for (std::size_t i = begin; i < end; ++i) out.push_back({xs[i], std::isfinite(ys[i]) ? ys[i] : nan});
        return;
    }
    // Column c holds x in [x_lo + c w, x_lo + (c + 1) w). Its end is found by binary search and
    // its samples scanned in one tight loop, so the cost per sample is a couple of compares.
    const double w = (x_hi - x_lo) / columns;
    std::size_t i = begin;
    while (i < end) {
        if (!std::isfinite(ys[i])) {
            out.push_back({xs[i], nan});
            ++i;
            continue;
        }
        const double column = std::floor((xs[i] - x_lo) / w);
        const double column_end = x_lo + (column + 1.0) * w;
        std::size_t stop = static_cast<std::size_t>(std::lower_bound(xs + i, xs + end, column_end) - xs);
        if (stop <= i) stop = i + 1;
        std::size_t lowest = i, highest = i, last = i;
        double low = ys[i], high = ys[i];
        constexpr double largest = std::numeric_limits<double>::max();
        for (std::size_t k = i + 1; k < stop; ++k) {
            const double y = ys[k];
            if (!(std::abs(y) <= largest)) break;  // NaN or infinite: a gap, the column ends at it
            last = k;
            if (y < low) {
                low = y;
                lowest = k;
            }
            if (y > high) {
                high = y;
                highest = k;
            }
        }
        const std::size_t picks[4] = {i, std::min(lowest, highest), std::max(lowest, highest), last};
        std::size_t previous = n;  // no index yet
        for (std::size_t p : picks) {
            if (p == previous) continue;
            out.push_back({xs[p], ys[p]});
            previous = p;
        }
        i = last + 1;
    }
}

}  // namespace pl::ui
