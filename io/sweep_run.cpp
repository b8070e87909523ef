#include "io/sweep_run.hpp"

#include "io/csv_writer.hpp"
#include "io/preset_io.hpp"
#include "io/preset_overrides.hpp"
#include "physics/stepping/thread_pool.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <numbers>
#include <thread>

namespace pl {

namespace {

using Opt = std::optional<double>;

const ParticleMetrics* particle_of(const VariantMetrics& m, std::size_t i) {
    return i < m.particles.size() ? &m.particles[i] : nullptr;
}

// A column of the table below reads one field of the selected particle's metrics.
template <auto Field>
Opt particle_field(const VariantMetrics& m, std::size_t i) {
    const ParticleMetrics* p = particle_of(m, i);
    if (!p) return std::nullopt;
    return Opt(p->*Field);
}

Opt bounces(const VariantMetrics& m, std::size_t i) {
    const ParticleMetrics* p = particle_of(m, i);
    return p ? Opt(static_cast<double>(p->bounces)) : std::nullopt;
}

Opt energy_lost(const VariantMetrics& m, std::size_t i) {
    const ParticleMetrics* p = particle_of(m, i);
    return p ? Opt(p->lost_drag + p->lost_bounce + p->lost_friction) : std::nullopt;
}

std::string joined_metric_names() {
    std::string names;
    for (const SweepMetric& m : sweep_metrics()) names += (names.empty() ? "" : ", ") + std::string(m.name);
    return names;
}

// FNV-1a 64 (Fowler, Noll, Vo): a field separator after each part keeps ("ab","c") != ("a","bc").
struct Fnv {
    std::uint64_t h = 0xcbf29ce484222325ull;
    void add(const std::string& s) {
        for (unsigned char c : s + '\x1f') h = (h ^ c) * 0x100000001b3ull;
    }
};

// Launch speed and elevation of a velocity, and its horizontal direction (x, z).
struct Launch {
    double speed = 0.0, elevation_deg = 0.0, hx = 1.0, hz = 0.0;
};
Launch launch_of(const Vec3& v) {
    Launch l;
    l.speed = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
    const double h = std::hypot(v.x, v.z);
    if (l.speed > 0.0) l.elevation_deg = std::atan2(v.y, h) * 180.0 / std::numbers::pi;
    if (h > 0.0) l.hx = v.x / h, l.hz = v.z / h;
    return l;
}

std::string describe_point(const SweepPlan& plan, std::size_t point) {
    const std::vector<std::string> names = plan.column_names(), values = plan.point_values(point);
    std::string text;
    for (std::size_t c = 0; c < names.size(); ++c) text += (c ? ", " : "") + names[c] + "=" + values[c];
    return fmt::format("point {} ({})", point, text);
}

}  // namespace

const std::vector<SweepMetric>& sweep_metrics() {
    static const std::vector<SweepMetric> table = {
        {"time_of_flight_s", "time of the first impact on a wall", &particle_field<&ParticleMetrics::first_impact_time>},
        {"range_at_first_impact_m", "horizontal distance from the start to the first impact",
         &particle_field<&ParticleMetrics::range_at_first_impact>},
        {"impact_speed_mps", "speed just before the first impact", &particle_field<&ParticleMetrics::first_impact_speed>},
        {"apex_height_m", "highest centre height over the floor", &particle_field<&ParticleMetrics::apex_height>},
        {"apex_time_s", "time of the apex", &particle_field<&ParticleMetrics::apex_time>},
        {"final_range_m", "horizontal distance from the start to the last position",
         &particle_field<&ParticleMetrics::final_range>},
        {"bounces", "rebounds (the impact that ends in rest is not one)", &bounces},
        {"time_to_rest_s", "time the particle stopped for good (empty: still moving)",
         &particle_field<&ParticleMetrics::time_to_rest>},
        {"all_at_rest_s", "first time every particle is stopped (empty: not all)",
         [](const VariantMetrics& m, std::size_t) { return m.all_at_rest_time; }},
        {"lost_to_drag_J", "energy dissipated by drag", &particle_field<&ParticleMetrics::lost_drag>},
        {"lost_to_bounces_J", "energy dissipated by bounces", &particle_field<&ParticleMetrics::lost_bounce>},
        {"lost_to_friction_J", "energy dissipated by friction", &particle_field<&ParticleMetrics::lost_friction>},
        {"energy_lost_J", "drag + bounces + friction", &energy_lost},
        {"wind_work_J", "work done by the wind", &particle_field<&ParticleMetrics::wind_work>},
    };
    return table;
}

std::string parse_metric_list(const std::string& text, std::vector<std::size_t>& out) {
    out.clear();
    std::size_t start = 0;
    for (;;) {
        const std::size_t comma = text.find(',', start);
        const std::string name = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        const auto& table = sweep_metrics();
        const auto it = std::find_if(table.begin(), table.end(), [&](const SweepMetric& m) { return name == m.name; });
        if (it == table.end())
            return fmt::format("--metrics: unknown metric '{}'; the metrics are {}", name, joined_metric_names());
        out.push_back(static_cast<std::size_t>(it - table.begin()));
        if (comma == std::string::npos) return "";
        start = comma + 1;
    }
}

std::string sweep_id(const SweepSpec& spec) {
    Fnv f;
    f.add(spec.preset_text);
    for (const auto* axes : {&spec.plan.axes, &spec.plan.samples}) {
        f.add(axes == &spec.plan.axes ? "axes" : "samples");
        for (const SweepAxis& a : *axes) f.add(a.path + "=" + a.spec);
    }
    f.add(fmt::format("{} {} {} {}", spec.plan.sample_count, spec.plan.seed, format_double(spec.duration_s), spec.particle));
    for (std::size_t m : spec.metrics) f.add(sweep_metrics()[m].name);
    return fmt::format("{:016x}", f.h);
}

std::string point_overrides(const SweepPlan& plan, std::size_t point, const Vec3* base_velocity,
                            std::vector<std::string>& out) {
    out.clear();
    const std::vector<std::string> names = plan.column_names(), values = plan.point_values(point);
    std::optional<Launch> launch;
    for (std::size_t c = 0; c < names.size(); ++c) {
        if (!is_launch_path(names[c])) {
            out.push_back(names[c] + "=" + values[c]);
            continue;
        }
        if (!base_velocity)
            return fmt::format("{}: the launch axes set particles[0].velocity, and the preset lists no particles", names[c]);
        if (!launch) launch = launch_of(*base_velocity);
        double x = 0.0;
        const auto r = std::from_chars(values[c].data(), values[c].data() + values[c].size(), x);
        const bool speed = names[c] == launch_speed_path;
        const bool bad = r.ec != std::errc() || r.ptr != values[c].data() + values[c].size() || !std::isfinite(x) ||
                         (speed ? x < 0.0 : std::abs(x) > 90.0);
        if (bad)
            return fmt::format("{}: must be {}, got {}", names[c], speed ? "a number >= 0" : "a number in [-90, 90]", values[c]);
        (speed ? launch->speed : launch->elevation_deg) = x;
    }
    if (launch) {
        const double e = launch->elevation_deg * std::numbers::pi / 180.0;
        const double h = launch->speed * std::cos(e);
        out.push_back(fmt::format("particles[0].velocity=[{},{},{}]", format_double(h * launch->hx),
                                  format_double(launch->speed * std::sin(e)), format_double(h * launch->hz)));
    }
    return "";
}

PreparedSweep prepare_sweep(const SweepSpec& spec, const std::vector<std::size_t>& points) {
    PreparedSweep out;
    out.points = points;
    const LoadResult base = parse_preset(spec.preset_text);
    if (!base.ok()) {
        out.error = "not a valid preset:\n" + base.error_text();
        return out;
    }
    const Vec3* base_velocity = base.scene->particles.empty() ? nullptr : &base.scene->particles.front().velocity;
    for (std::size_t v = 0; v < variant_count(*base.scene); ++v) {
        const std::string& label = base.scene->variants.empty() ? "" : base.scene->variants[v].label;
        out.variant_names.push_back(label.empty() ? std::to_string(v) : label);
    }
    std::vector<std::string> overrides;
    std::size_t next = 0;  // next entry of `points` (sorted) whose scene is kept
    for (std::size_t p = 0; p < spec.plan.point_count(); ++p) {
        std::string error = point_overrides(spec.plan, p, base_velocity, overrides);
        OverrideResult set = error.empty() ? apply_preset_overrides(spec.preset_text, overrides) : OverrideResult{};
        if (error.empty()) error = set.error;
        LoadResult loaded = error.empty() ? parse_preset(set.text) : LoadResult{};
        if (error.empty() && !loaded.ok()) error = loaded.error_text();
        if (error.empty()) error = plan_duration(*loaded.scene, spec.duration_s).error;
        if (error.empty() && spec.particle >= initial_particles(*loaded.scene).size())
            error = fmt::format("--particle {}: the scene has {} particles", spec.particle,
                                initial_particles(*loaded.scene).size());
        if (!error.empty()) {
            out.error = describe_point(spec.plan, p) + ": " + error;
            out.scenes.clear();
            return out;
        }
        if (next < points.size() && points[next] == p) {
            out.scenes.push_back(std::move(*loaded.scene));
            ++next;
        }
    }
    return out;
}

SweepResults run_sweep(const PreparedSweep& prepared, double duration_s, const SweepRunOptions& options) {
    SweepResults out;
    const std::size_t total = prepared.scenes.size();
    out.points.resize(total);
    std::atomic<std::size_t> next{0}, done{0};
    std::atomic<bool> stopped{false};
    auto worker = [&] {
        CompareOptions compare;
        compare.duration_s = duration_s;
        compare.threads = 1;  // the points run in parallel; a scene on one thread keeps its results thread-count free
        compare.cancel = options.cancel;
        for (;;) {
            if (options.cancel && options.cancel->load(std::memory_order_relaxed)) {
                stopped = true;
                return;
            }
            const std::size_t i = next.fetch_add(1);
            if (i >= total) return;
            out.points[i] = run_comparison(prepared.scenes[i], compare);
            if (out.points[i].cancelled) stopped = true;
            const std::size_t d = done.fetch_add(1) + 1;
            if (options.progress) options.progress(d, total);
        }
    };
    const std::size_t threads = options.threads > 0 ? static_cast<std::size_t>(options.threads)
                                                    : static_cast<std::size_t>(hardware_threads());
    std::vector<std::thread> pool;
    for (std::size_t t = 1; t < std::min(threads, std::max<std::size_t>(total, 1)); ++t) pool.emplace_back(worker);
    worker();
    for (std::thread& t : pool) t.join();
    out.cancelled = stopped;
    return out;
}

}  // namespace pl
