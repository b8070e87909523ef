#include "io/sweep_plan.hpp"

#include "io/csv_writer.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <numbers>
#include <optional>

namespace pl {

namespace {

std::optional<double> parse_number(const std::string& text) {
    double v = 0.0;
    const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
    if (text.empty() || r.ec != std::errc() || r.ptr != text.data() + text.size() || !std::isfinite(v)) return std::nullopt;
    return v;
}

std::optional<std::size_t> parse_count(const std::string& text) {
    std::size_t v = 0;
    const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
    if (text.empty() || r.ec != std::errc() || r.ptr != text.data() + text.size()) return std::nullopt;
    return v;
}

// Splits on commas that are not inside brackets or braces, so a list item may be [5,5,0].
std::vector<std::string> split_top_level(const std::string& text) {
    std::vector<std::string> items(1);
    int depth = 0;
    for (char c : text) {
        if (c == '[' || c == '{') ++depth;
        if (c == ']' || c == '}') --depth;
        if (c == ',' && depth == 0) items.emplace_back();
        else items.back() += c;
    }
    return items;
}

// "PATH=REST" -> path, rest; an error names the option when there is no '=' or no path.
std::string split_spec(const char* option, const std::string& spec, SweepAxis& out, std::string& rest) {
    const std::size_t eq = spec.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == spec.size())
        return fmt::format("{} '{}': expected PATH=VALUES with PATH a preset path such as drag.cd", option, spec);
    out = SweepAxis{};
    out.path = spec.substr(0, eq);
    rest = spec.substr(eq + 1);
    out.spec = rest;
    if (out.path.rfind("launch.", 0) == 0 && !is_launch_path(out.path))
        return fmt::format("{} {}: unknown launch axis; the launch axes are {} and {}", option, out.path,
                           launch_speed_path, launch_elevation_path);
    return "";
}

// SplitMix64's finaliser (Steele, Lea, Flood 2014): a bijective mix with full avalanche, so
// hashing (seed, axis, k, draw) gives independent-looking 64-bit words without any state.
std::uint64_t mix64(std::uint64_t z) {
    z += 0x9e3779b97f4a7c15ull;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

// Uniform in (0, 1]: 53 random bits, never 0 (the Box-Muller logarithm needs u > 0).
double unit_draw(std::uint64_t seed, std::size_t axis, std::size_t k, unsigned draw) {
    const std::uint64_t h = mix64(mix64(mix64(mix64(seed) ^ axis) ^ k) ^ draw);
    return static_cast<double>((h >> 11) + 1) * 0x1.0p-53;
}

}  // namespace

bool is_launch_path(const std::string& path) { return path == launch_speed_path || path == launch_elevation_path; }

std::size_t SweepPlan::point_count() const {
    std::size_t n = 1;
    for (const SweepAxis& a : axes) n *= a.values.size();
    return samples.empty() ? n : n * sample_count;
}

std::vector<std::string> SweepPlan::column_names() const {
    std::vector<std::string> names;
    for (const SweepAxis& a : axes) names.push_back(a.path);
    for (const SweepAxis& a : samples) names.push_back(a.path);
    return names;
}

std::vector<std::string> SweepPlan::point_values(std::size_t point) const {
    std::vector<std::string> values(axes.size() + samples.size());
    const std::size_t k = samples.empty() ? 0 : point % sample_count;
    std::size_t grid = samples.empty() ? point : point / sample_count;
    for (std::size_t i = axes.size(); i-- > 0;) {  // the last axis varies fastest
        values[i] = axes[i].values[grid % axes[i].values.size()];
        grid /= axes[i].values.size();
    }
    for (std::size_t j = 0; j < samples.size(); ++j)
        values[axes.size() + j] = format_double(sample_value(samples[j], seed, j, k));
    return values;
}

std::string parse_axis(const std::string& spec, SweepAxis& out) {
    std::string rest;
    if (std::string e = split_spec("--axis", spec, out, rest); !e.empty()) return e;
    const std::size_t colon = rest.find(':');
    if (colon != std::string::npos && rest.find_first_of("[{\"") == std::string::npos) {
        const std::size_t colon2 = rest.find(':', colon + 1);
        const std::optional<double> low = parse_number(rest.substr(0, colon));
        const std::optional<double> high =
            colon2 == std::string::npos ? std::nullopt : parse_number(rest.substr(colon + 1, colon2 - colon - 1));
        const std::optional<std::size_t> count =
            colon2 == std::string::npos ? std::nullopt : parse_count(rest.substr(colon2 + 1));
        if (!low || !high || !count || *count == 0)
            return fmt::format("--axis {}: expected LOW:HIGH:COUNT (numbers, COUNT >= 1), got '{}'", out.path, rest);
        // x_i = low + (high - low) i / (count - 1): both ends exact, and whole steps stay whole.
        for (std::size_t i = 0; i < *count; ++i) {
            const double x = *count == 1 ? *low
                                         : *low + (*high - *low) * static_cast<double>(i) / static_cast<double>(*count - 1);
            out.values.push_back(format_double(x));
        }
        return "";
    }
    for (const std::string& item : split_top_level(rest)) {
        if (item.empty()) return fmt::format("--axis {}: empty value in the list '{}'", out.path, rest);
        out.values.push_back(item);
    }
    return "";
}

std::string parse_sample(const std::string& spec, SweepAxis& out) {
    std::string rest;
    if (std::string e = split_spec("--sample", spec, out, rest); !e.empty()) return e;
    out.sampled = true;
    const std::size_t open = rest.find('(');
    const std::size_t comma = rest.find(',');
    const std::string name = rest.substr(0, open);
    const bool shaped = open != std::string::npos && comma != std::string::npos && comma > open && rest.back() == ')';
    const std::string a_text = shaped ? rest.substr(open + 1, comma - open - 1) : "";
    const std::string b_text = shaped ? rest.substr(comma + 1, rest.size() - comma - 2) : "";
    const std::optional<double> a = parse_number(a_text), b = parse_number(b_text);
    if ((name != "normal" && name != "uniform") || !a || !b)
        return fmt::format("--sample {}: expected normal(MEAN,SD) or uniform(LOW,HIGH), got '{}'", out.path, rest);
    out.distribution = name == "normal" ? Distribution::normal : Distribution::uniform;
    out.a = a.value();
    out.b = b.value();
    if (out.distribution == Distribution::normal && !(out.b >= 0.0))
        return fmt::format("--sample {}: the standard deviation must be >= 0, got {}", out.path, out.b);
    if (out.distribution == Distribution::uniform && !(out.b >= out.a))
        return fmt::format("--sample {}: uniform(LOW,HIGH) needs LOW <= HIGH, got '{}'", out.path, rest);
    return "";
}

double sample_value(const SweepAxis& axis, std::uint64_t seed, std::size_t axis_index, std::size_t k) {
    const double u1 = unit_draw(seed, axis_index, k, 0);
    if (axis.distribution == Distribution::uniform) return axis.a + (axis.b - axis.a) * (1.0 - u1);  // [low, high)
    // Box-Muller (1958): z = sqrt(-2 ln u1) cos(2 pi u2) is standard normal for independent
    // uniform u1 in (0, 1] and u2.
    const double u2 = unit_draw(seed, axis_index, k, 1);
    return axis.a + axis.b * std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

std::string parse_shard(const std::string& text, bool strided, Shard& out) {
    const std::size_t slash = text.find('/');
    const std::optional<std::size_t> i = slash == std::string::npos ? std::nullopt : parse_count(text.substr(0, slash));
    const std::optional<std::size_t> n = slash == std::string::npos ? std::nullopt : parse_count(text.substr(slash + 1));
    if (!i || !n || *n == 0 || *i >= *n)
        return fmt::format("--shard: expected I/N with 0 <= I < N (the I-th of N slices), got '{}'", text);
    out = Shard{*i, *n, strided};
    return "";
}

std::vector<std::size_t> shard_points(const Shard& shard, std::size_t total) {
    std::vector<std::size_t> points;
    if (shard.strided) {
        for (std::size_t p = shard.index; p < total; p += shard.count) points.push_back(p);
        return points;
    }
    // Block I is [I total / N, (I + 1) total / N): sizes differ by at most one.
    const std::size_t begin = shard.index * total / shard.count, end = (shard.index + 1) * total / shard.count;
    for (std::size_t p = begin; p < end; ++p) points.push_back(p);
    return points;
}

}  // namespace pl
