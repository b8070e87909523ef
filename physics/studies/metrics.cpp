#include "physics/studies/metrics.hpp"

#include "physics/stepping/energy.hpp"
#include "physics/stepping/thread_pool.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <unordered_map>
#include <cmath>

namespace pl {

namespace {

double horizontal_distance(const Vec3& a, const Vec3& b) { return std::hypot(a.x - b.x, a.z - b.z); }

bool is_impact(const Event& e) {
    return e.wall >= 0 && (e.kind == EventKind::bounce || e.kind == EventKind::rest);
}

std::optional<double> optional_difference(const std::optional<double>& a, const std::optional<double>& b) {
    if (a && b) return *a - *b;
    return std::nullopt;
}

}  // namespace

MetricsTracker start_metrics(const Simulation& sim) {
    MetricsTracker m;
    const ParticleState& s = sim.state();
    const std::size_t n = s.size();
    m.floor_y = sim.model().room.floor_y();
    m.start_position.resize(n);
    m.prev.resize(n);
    m.particles.resize(n);
    m.stopped_since.assign(n, std::nullopt);
    for (std::size_t i = 0; i < n; ++i) {
        m.start_position[i] = s.position(i);
        update_step_start(m.prev[i], sim, i);
        m.particles[i].apex_height = s.y[i] - m.floor_y;
        m.particles[i].apex_time = sim.time();
    }
    m.prev_time = sim.time();
    m.prev_steps = sim.step_count();
    return m;
}

namespace {

// The traces of the particles whose latest step is replayed, each replayed once, on demand.
class StepTraces {
public:
    StepTraces(const MetricsTracker& m, const Simulation& sim)
        : m_(m), sim_(sim), one_step_(sim.step_count() == m.prev_steps + 1) {}
    const StepTrace* of(std::uint32_t i) {
        auto found = traces_.find(i);
        if (found == traces_.end())
            found = traces_.emplace(i, one_step_ ? replay_step(sim_, i, m_.prev[i]) : std::nullopt).first;
        return found->second ? &*found->second : nullptr;
    }

private:
    const MetricsTracker& m_;
    const Simulation& sim_;
    const bool one_step_;
    std::unordered_map<std::uint32_t, std::optional<StepTrace>> traces_;
};

// The first impact's position: located by the replayed step, or (no replay: the particle was
// launched again within the step) the state before the step extrapolated linearly to it.
Vec3 first_impact_position(const MetricsTracker& m, StepTraces& traces, const Event& e) {
    if (const StepTrace* trace = traces.of(e.particle))
        for (const StepTrace::Impact& hit : trace->impacts)
            if (hit.t == e.t) return hit.x;
    const StepStart& before = m.prev[e.particle];
    return before.x + (e.t - m.prev_time) * before.v;
}

}  // namespace

void observe_step(MetricsTracker& m, const Simulation& sim, const std::vector<Event>& new_events,
                  double physics_seconds) {
    StepTraces traces(m, sim);
    // Particles that hit the floor in this step, sorted below: the only impact that turns a falling
    // particle upwards (friction on a side wall slows the vertical velocity, never reverses it).
    std::vector<std::uint32_t> floor_hits;
    for (const Event& e : new_events) {
        if (e.particle >= m.particles.size()) continue;
        ParticleMetrics& p = m.particles[e.particle];
        if (is_impact(e) && e.wall == Wall::y_min) floor_hits.push_back(e.particle);
        if (is_impact(e) && !p.first_impact_time) {
            p.first_impact_time = e.t;
            p.first_impact_wall = e.wall;
            p.first_impact_speed = e.speed_in;
            p.range_at_first_impact = horizontal_distance(first_impact_position(m, traces, e), m.start_position[e.particle]);
        }
        if (e.kind == EventKind::bounce && e.wall >= 0) ++p.bounces;
        if ((e.kind == EventKind::rest || e.kind == EventKind::stop) && e.speed_out == 0.0)
            m.stopped_since[e.particle] = e.t;
    }
    std::sort(floor_hits.begin(), floor_hits.end());
    const ParticleState& s = sim.state();
    const double t = sim.time();
    // A step can hold a highest point inside when the particle rose at its start (or bounced off
    // the floor in it) and no longer rises fast at its end: |g| dt covers the lag of semi-implicit
    // Euler's step-end velocity (a dt / 2) behind its trajectory's. It is replayed when that point
    // could beat the apex so far: it lies less than reach(v0, v1) above the step's ends (twice
    // its speeds over its length, and a step of gravity), so the lower arcs after the first are
    // not replayed.
    const double g = glm::length(sim.model().world.gravity), h = sim.dt();
    const double turn_margin = g * h;
    auto reach = [&](const Vec3& v0, const Vec3& v1) { return 2.0 * h * (glm::length(v0) + glm::length(v1)) + g * h * h; };
    for (std::size_t i = 0; i < s.size(); ++i) {
        ParticleMetrics& p = m.particles[i];
        const double height = s.y[i] - m.floor_y;
        if (height > p.apex_height) {
            p.apex_height = height;
            p.apex_time = t;
        }
        const StepStart& before = m.prev[i];
        const bool rose = before.v.y > 0.0 || std::binary_search(floor_hits.begin(), floor_hits.end(), i);
        if (rose && s.vy[i] <= turn_margin &&
            std::max(before.x.y, s.y[i]) - m.floor_y + reach(before.v, s.velocity(i)) > p.apex_height)
            if (const StepTrace* trace = traces.of(static_cast<std::uint32_t>(i)); trace && trace->apex_y - m.floor_y > p.apex_height) {
                p.apex_height = trace->apex_y - m.floor_y;
                p.apex_time = trace->apex_t;
            }
        update_step_start(m.prev[i], sim, i);
    }
    m.prev_time = t;
    m.prev_steps = sim.step_count();
    m.physics_seconds += physics_seconds;
}

VariantMetrics metrics_of(const MetricsTracker& m, const Simulation& sim) {
    VariantMetrics out;
    out.label = sim.model().label;
    out.particles = m.particles;
    const ParticleState& s = sim.state();
    bool all_rest = s.size() > 0;
    double latest_rest = 0.0;
    for (std::size_t i = 0; i < s.size(); ++i) {
        ParticleMetrics& p = out.particles[i];
        p.final_range = horizontal_distance(s.position(i), m.start_position[i]);
        p.time_to_rest = sim.at_rest(i) ? m.stopped_since[i] : std::nullopt;
        if (p.time_to_rest) latest_rest = std::max(latest_rest, *p.time_to_rest);
        else all_rest = false;
        p.lost_drag = s.dissipated_drag[i];
        p.lost_bounce = s.dissipated_bounce[i];
        p.lost_friction = s.dissipated_friction[i];
        p.wind_work = s.wind_work[i];
        out.lost_drag += p.lost_drag;
        out.lost_bounce += p.lost_bounce;
        out.lost_friction += p.lost_friction;
        out.wind_work += p.wind_work;
    }
    if (all_rest) out.all_at_rest_time = latest_rest;
    out.energy_residual = total_energy(s, sim.model().world.gravity, sim.model().room).residual();
    out.simulated_seconds = sim.time();
    out.steps = sim.step_count();
    out.physics_seconds = m.physics_seconds;
    return out;
}

MetricsDifference metrics_difference(const VariantMetrics& value, const VariantMetrics& baseline,
                                     std::size_t particle) {
    MetricsDifference d;
    if (particle < value.particles.size() && particle < baseline.particles.size()) {
        const ParticleMetrics& a = value.particles[particle];
        const ParticleMetrics& b = baseline.particles[particle];
        d.first_impact_time = optional_difference(a.first_impact_time, b.first_impact_time);
        d.range_at_first_impact = optional_difference(a.range_at_first_impact, b.range_at_first_impact);
        d.time_to_rest = optional_difference(a.time_to_rest, b.time_to_rest);
        d.apex_height = a.apex_height - b.apex_height;
        d.final_range = a.final_range - b.final_range;
        d.bounces = static_cast<long long>(a.bounces) - static_cast<long long>(b.bounces);
    }
    d.all_at_rest_time = optional_difference(value.all_at_rest_time, baseline.all_at_rest_time);
    d.lost_drag = value.lost_drag - baseline.lost_drag;
    d.lost_bounce = value.lost_bounce - baseline.lost_bounce;
    d.lost_friction = value.lost_friction - baseline.lost_friction;
    d.cost = value.cost() - baseline.cost();
    return d;
}

std::uint64_t catch_up(Simulation& sim, double t) {
    const std::uint64_t n = sim.steps_to(t);
    sim.step_n(n);
    return n;
}

DurationPlan plan_duration(const Scene& scene, double duration_s) {
    DurationPlan plan;
    if (!(duration_s > 0.0) || !std::isfinite(duration_s)) {
        plan.error = fmt::format("must be a finite number > 0, got {}", duration_s);
        return plan;
    }
    plan.base_dt = INFINITY;
    for (std::size_t v = 0; v < variant_count(scene); ++v) {
        const Model m = model_for_variant(scene, v);
        const double dt = m.integrator.dt;
        const double steps = duration_s / dt;
        // Past 2^53 a double cannot tell whole numbers of steps apart (and 1e308 / 5e-324 is inf).
        if (!(steps <= 9007199254740992.0)) {
            plan.error = fmt::format("{} s is {:.3g} steps of dt = {} s{}, more than can be counted (2^53)", duration_s,
                                     steps, dt, m.label.empty() ? "" : fmt::format(" (variant '{}')", m.label));
            return plan;
        }
        if (std::abs(steps - std::round(steps)) > 1e-9 * std::max(1.0, steps) || std::round(steps) < 1.0) {
            const double nearest = std::max(1.0, std::round(steps)) * dt;
            plan.error = fmt::format("{} s is not a whole number of steps of dt = {} s{}; the nearest is {} s",
                                     duration_s, dt, m.label.empty() ? "" : fmt::format(" (variant '{}')", m.label),
                                     nearest);
            return plan;
        }
        plan.base_dt = std::min(plan.base_dt, dt);
    }
    plan.base_steps = static_cast<std::uint64_t>(std::llround(duration_s / plan.base_dt));
    return plan;
}

Comparison run_comparison(const Scene& scene, const CompareOptions& options) {
    Comparison out;
    out.duration_s = options.duration_s;
    const DurationPlan plan = plan_duration(scene, options.duration_s);
    if (!plan.error.empty()) {
        out.error = plan.error;
        return out;
    }
    const std::vector<ParticleSpec> particles = initial_particles(scene);
    std::vector<Simulation> sims;
    std::vector<MetricsTracker> trackers;
    for (std::size_t v = 0; v < variant_count(scene); ++v) {
        sims.emplace_back(model_for_variant(scene, v), particles);
        // An explicit count (same results as 0 = all) spares a hardware query on every step.
        sims.back().set_threads(options.threads > 0 ? options.threads : hardware_threads());
        trackers.push_back(start_metrics(sims.back()));
    }
    using clock = std::chrono::steady_clock;
    const std::uint64_t report_every = std::max<std::uint64_t>(1, plan.base_steps / 100);
    for (std::uint64_t k = 1; k <= plan.base_steps; ++k) {
        if (options.cancel && options.cancel->load(std::memory_order_relaxed)) {
            out.cancelled = true;
            break;
        }
        const double t = static_cast<double>(k) * plan.base_dt;
        for (std::size_t v = 0; v < sims.size(); ++v) {
            const auto start = clock::now();
            const std::uint64_t n = catch_up(sims[v], t);
            const double seconds = std::chrono::duration<double>(clock::now() - start).count();
            if (n > 0) observe_step(trackers[v], sims[v], sims[v].drain_events(), seconds);
        }
        if (options.progress && k % report_every == 0)
            options.progress(static_cast<double>(k) / static_cast<double>(plan.base_steps));
    }
    for (std::size_t v = 0; v < sims.size(); ++v) out.variants.push_back(metrics_of(trackers[v], sims[v]));
    return out;
}

}  // namespace pl
