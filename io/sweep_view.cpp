#include "io/sweep_view.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>

namespace pl {

std::string axis_spec(const SweepAxisChoice& axis) {
    if (axis.list) return axis.path + "=" + axis.values;
    // {} is fmt's shortest round-trip form, so the text parses back to the same doubles.
    return fmt::format("{}={}:{}:{}", axis.path, axis.low, axis.high, axis.count);
}

std::string sample_spec(const SweepChoices& c) {
    const char* name = c.distribution == Distribution::normal ? "normal" : "uniform";
    return fmt::format("{}={}({},{})", c.sample_path, name, c.a, c.b);
}

std::string spec_from_choices(const SweepChoices& c, const std::string& preset_text, SweepSpec& out) {
    out = SweepSpec{};
    out.preset_text = preset_text;
    out.duration_s = c.duration_s;
    if (!(c.duration_s > 0.0) || !std::isfinite(c.duration_s)) return fmt::format("duration: {} is not a positive number of seconds", c.duration_s);
    if (c.monte_carlo) {
        if (c.samples == 0) return "samples: give at least 1";
        if (std::string e = parse_sample(sample_spec(c), out.plan.samples.emplace_back()); !e.empty()) return e;
        out.plan.sample_count = c.samples;
        out.plan.seed = c.seed;
    } else {
        if (std::string e = parse_axis(axis_spec(c.first), out.plan.axes.emplace_back()); !e.empty()) return e;
        if (c.two_axes) {
            if (c.second.path == c.first.path) return "second axis: " + c.second.path + " is the first axis already";
            if (std::string e = parse_axis(axis_spec(c.second), out.plan.axes.emplace_back()); !e.empty()) return e;
        }
    }
    for (std::size_t m = 0; m < sweep_metrics().size(); ++m) out.metrics.push_back(m);
    return "";
}

std::vector<std::optional<double>> metric_values(const SweepSpec& spec, const PreparedSweep& prepared,
                                                 const SweepResults& results, std::size_t metric, std::size_t variant) {
    std::vector<std::optional<double>> out(prepared.points.size());
    if (metric >= sweep_metrics().size()) return out;
    for (std::size_t i = 0; i < out.size() && i < results.points.size(); ++i) {
        const Comparison& c = results.points[i];
        if (c.cancelled || variant >= c.variants.size()) continue;
        out[i] = sweep_metrics()[metric].of(c.variants[variant], spec.particle);
    }
    return out;
}

std::optional<std::vector<double>> numeric_values(const SweepAxis& axis) {
    std::vector<double> out;
    for (const std::string& v : axis.values) {
        double d = 0.0;
        const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), d);
        if (ec != std::errc() || end != v.data() + v.size()) return std::nullopt;
        out.push_back(d);
    }
    return out;
}

std::vector<SweepSeries> line_series(const SweepPlan& plan, const PreparedSweep& prepared,
                                     const std::vector<std::optional<double>>& values) {
    if (plan.axes.empty()) return {};
    const SweepAxis& first = plan.axes[0];
    const std::optional<std::vector<double>> xs = numeric_values(first);
    // Points are row-major over the grid axes (first slowest), the samples fastest.
    std::size_t inner = std::max<std::size_t>(plan.sample_count, 1);
    for (std::size_t a = 1; a < plan.axes.size(); ++a) inner *= plan.axes[a].values.size();
    const std::size_t per_series = std::max<std::size_t>(plan.sample_count, 1);
    std::map<std::size_t, SweepSeries> series;  // by the index of the value of the axes after the first
    for (std::size_t i = 0; i < prepared.points.size() && i < values.size(); ++i) {
        if (!values[i]) continue;
        const std::size_t p = prepared.points[i];
        const std::size_t i0 = p / inner, key = (p % inner) / per_series;
        SweepSeries& s = series[key];
        if (s.label.empty() && plan.axes.size() > 1) {
            const std::vector<std::string> names = plan.column_names(), row = plan.point_values(p);
            for (std::size_t a = 1; a < plan.axes.size(); ++a) s.label += (a > 1 ? ", " : "") + names[a] + "=" + row[a];
        }
        s.x.push_back(xs ? (*xs)[i0] : static_cast<double>(i0));
        s.y.push_back(*values[i]);
        s.points.push_back(p);
    }
    std::vector<SweepSeries> out;
    for (auto& [key, s] : series) out.push_back(std::move(s));
    return out;
}

std::vector<double> cell_edges(const std::vector<double>& v) {
    if (v.empty()) return {};
    if (v.size() == 1) return {v[0] - 0.5, v[0] + 0.5};
    std::vector<double> e{v[0] - (v[1] - v[0]) / 2};
    for (std::size_t i = 0; i + 1 < v.size(); ++i) e.push_back((v[i] + v[i + 1]) / 2);
    e.push_back(v.back() + (v.back() - v[v.size() - 2]) / 2);
    return e;
}

Histogram histogram(const std::vector<std::optional<double>>& values, std::size_t bins) {
    Histogram h;
    h.counts.assign(std::max<std::size_t>(bins, 1), 0);
    double lo = INFINITY, hi = -INFINITY, sum = 0.0;
    std::size_t n = 0;
    for (const auto& v : values) {
        if (!v || !std::isfinite(*v)) {
            ++h.missing;
            continue;
        }
        lo = std::min(lo, *v);
        hi = std::max(hi, *v);
        sum += *v;
        ++n;
    }
    if (n == 0) return h;
    h.mean = sum / static_cast<double>(n);
    double squares = 0.0;
    for (const auto& v : values)
        if (v && std::isfinite(*v)) squares += (*v - h.mean) * (*v - h.mean);
    h.sd = n > 1 ? std::sqrt(squares / static_cast<double>(n - 1)) : 0.0;
    // All values equal: one bin of width 1 centred on them rather than a zero width.
    h.width = hi > lo ? (hi - lo) / static_cast<double>(h.counts.size()) : 1.0;
    h.low = hi > lo ? lo : lo - 0.5;
    for (const auto& v : values) {
        if (!v || !std::isfinite(*v)) continue;
        const auto bin = static_cast<std::size_t>(std::max(0.0, std::floor((*v - h.low) / h.width)));
        ++h.counts[std::min(bin, h.counts.size() - 1)];
    }
    return h;
}

std::optional<std::size_t> best_index(const std::vector<std::optional<double>>& values) {
    std::optional<std::size_t> best;
    for (std::size_t i = 0; i < values.size(); ++i)
        if (values[i] && (!best || *values[i] > *values[*best])) best = i;
    return best;
}

}  // namespace pl
