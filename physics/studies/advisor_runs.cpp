#include "physics/studies/advisor_runs.hpp"

#include "physics/stepping/contact.hpp"
#include "physics/stepping/simulation.hpp"

#include <algorithm>
#include <cmath>

namespace pl {

namespace {

std::uint8_t floor_walls(const Model& model) {
    std::uint8_t mask = 0;
    for (int w = 0; w < wall_count; ++w)
        if (glm::dot(model.world.gravity, RoomBounds::inward_normal(w)) < 0.0) mask |= static_cast<std::uint8_t>(1u << w);
    return mask;
}

// Per-step bookkeeping of one run: events (landing, impacts, rest) and the apex.
struct Recorder {
    Recorder(const Model& m, const std::vector<ParticleSpec>& p) : model(m), particles(p) {}
    const Model& model;
    const std::vector<ParticleSpec>& particles;
    std::uint8_t floor_mask = floor_walls(model);
    double floor_y = model.room.floor_y();
    std::vector<Vec3> prev_x, prev_v;
    std::vector<std::optional<double>> stopped_since;  // time of the last event that left v == 0
    RunOutcome out;

    void start(const Simulation& sim) {
        const std::size_t n = particles.size();
        prev_x.resize(n);
        prev_v.resize(n);
        stopped_since.assign(n, std::nullopt);
        out.particles.resize(n);
        for (std::size_t i = 0; i < n; ++i) {
            out.particles[i].start = sim.state().position(i);
            out.particles[i].apex_height = particles[i].position.y - floor_y;
        }
    }

    void event(const Event& e, double t0) {
        const std::size_t i = e.particle;
        ParticleOutcome& p = out.particles[i];
        if ((e.kind == EventKind::rest || e.kind == EventKind::stop) && e.speed_out == 0.0) stopped_since[i] = e.t;
        else if (e.kind == EventKind::bounce || e.kind == EventKind::lift) stopped_since[i] = std::nullopt;
        const bool floor_impact = e.wall >= 0 && (floor_mask & (1u << e.wall)) &&
                                  (e.kind == EventKind::bounce || e.kind == EventKind::rest);
        if (!floor_impact) return;
        if (p.impact_speeds.size() < static_cast<std::size_t>(advice_impacts)) p.impact_speeds.push_back(e.speed_in);
        if (p.landing) return;
        // Linear extrapolation of the state before the step to the impact time (the impact
        // wall's coordinate is exact: the sphere touches it).
        Vec3 at = prev_x[i] + (e.t - t0) * prev_v[i];
        at[RoomBounds::axis(e.wall)] = RoomBounds(model.room).contact_plane(e.wall, particles[i].radius);
        p.landing = at;
        p.landing_time = e.t;
    }
};

}  // namespace

RunOutcome observe_run(const Model& model, const std::vector<ParticleSpec>& particles, double max_duration,
                       bool measure_numbers, const std::atomic<bool>* cancel) {
    Simulation sim(model, particles);
    sim.set_threads(1);  // a hundred particles at most
    Recorder r(model, particles);
    r.start(sim);
    const std::size_t n = particles.size();
    const double g = glm::length(model.world.gravity);
    const auto max_steps = static_cast<std::uint64_t>(std::ceil(max_duration / sim.dt()));
    bool all_done = n == 0;
    for (std::uint64_t k = 0; k < max_steps && !all_done; ++k) {
        if (cancel && k % 1024 == 0 && cancel->load(std::memory_order_relaxed)) break;
        const double t0 = sim.time();
        for (std::size_t i = 0; i < n; ++i) {
            r.prev_x[i] = sim.state().position(i);
            r.prev_v[i] = sim.state().velocity(i);
            if (!measure_numbers || r.out.particles[i].landing || sim.state().frozen[i]) continue;
            const Vec3 u = r.prev_v[i] - sim.wind().at(r.prev_x[i], t0);
            r.out.max_mach = std::max(r.out.max_mach, glm::length(u) / speed_of_sound_mps);
            if (g > 0.0)
                r.out.max_drag_to_weight =
                    std::max(r.out.max_drag_to_weight, glm::length(sim.acceleration(i) - model.world.gravity) / g);
        }
        sim.step();
        for (const Event& e : sim.drain_events())
            if (e.particle < n) r.event(e, t0);
        all_done = true;
        for (std::size_t i = 0; i < n; ++i) {
            ParticleOutcome& p = r.out.particles[i];
            if (!p.landing) p.apex_height = std::max(p.apex_height, sim.state().y[i] - r.floor_y);
            all_done = all_done && (sim.state().frozen[i] || sim.at_rest(i));
        }
    }
    if (measure_numbers && model.drag.model != DragModel::none) {
        const ReRange seen = sim.observed_reynolds();
        if (seen.hi > 0.0) {
            r.out.re_min = seen.lo;
            r.out.re_max = seen.hi;
        }
    }
    for (std::size_t i = 0; i < n; ++i) {
        ParticleOutcome& p = r.out.particles[i];
        p.end = sim.state().position(i);
        if (sim.at_rest(i)) p.rest_time = r.stopped_since[i];
    }
    r.out.end_time = sim.time();
    return std::move(r.out);
}

namespace {

double horizontal_distance(const Vec3& a, const Vec3& b) { return std::hypot(a.x - b.x, a.z - b.z); }

// One particle's difference for one metric, and how far it is past its tolerance.
struct Candidate {
    MetricDelta d;
    double excess = 0.0;  // |difference| / tolerance
};

void consider(MetricDelta& best, double& best_excess, const Candidate& c) {
    if (c.d.beyond_tolerance) best.beyond_tolerance = true;
    if (best.measured && c.excess <= best_excess) return;
    const bool beyond = best.beyond_tolerance;
    best = c.d;
    best.beyond_tolerance = beyond;
    best_excess = c.excess;
}

Candidate candidate(AdviceMetric m, double value, double baseline, bool at_least, std::size_t particle,
                    const AdviceTolerances& tol) {
    Candidate c;
    c.d.measured = true;
    c.d.value = value;
    c.d.baseline = baseline;
    c.d.difference = m == AdviceMetric::landing_point ? value : value - baseline;
    c.d.at_least = at_least;
    c.d.particle = particle;
    const double limit = tol.limit(m, baseline);
    c.excess = std::abs(c.d.difference) / limit;
    c.d.beyond_tolerance = std::abs(c.d.difference) > limit;
    return c;
}

// A time that one run may not have reached: the run's end time is then a lower bound.
std::optional<Candidate> time_candidate(AdviceMetric m, const std::optional<double>& v, const std::optional<double>& b,
                                        double v_end, double b_end, std::size_t i, const AdviceTolerances& tol) {
    if (!v && !b) return std::nullopt;
    return candidate(m, v.value_or(v_end), b.value_or(b_end), !v || !b, i, tol);
}

// The signed differences measured in both runs, summed for their mean and standard error.
struct Tally {
    double sum = 0.0, sum_of_squares = 0.0;
    std::size_t count = 0;
    void add(double d) {
        sum += d;
        sum_of_squares += d * d;
        ++count;
    }
    void finish(MetricDelta& out) const {
        out.samples = count;
        if (count == 0) return;
        out.mean = sum / static_cast<double>(count);
        if (count < 2) return;
        const double variance = std::max(0.0, (sum_of_squares - sum * out.mean) / static_cast<double>(count - 1));
        out.standard_error = std::sqrt(variance / static_cast<double>(count));
    }
};

}  // namespace

void compare_runs(const RunOutcome& value, const RunOutcome& baseline, const AdviceTolerances& tol, ModelRun& out) {
    std::array<double, advice_metric_count> excess{};
    std::array<Tally, advice_metric_count> tally{};
    // Each particle's (and impact's) candidate: the largest past its tolerance is kept, and the
    // signed differences that both runs reached are tallied (the landing point's is a distance,
    // never signed: not tallied).
    auto take = [&](AdviceMetric m, const Candidate& c) {
        const auto k = static_cast<std::size_t>(m);
        consider(out.metrics[k], excess[k], c);
        if (!c.d.at_least && m != AdviceMetric::landing_point) tally[k].add(c.d.difference);
    };
    for (std::size_t i = 0; i < value.particles.size() && i < baseline.particles.size(); ++i) {
        const ParticleOutcome& v = value.particles[i];
        const ParticleOutcome& b = baseline.particles[i];
        for (AdviceMetric m : {AdviceMetric::landing_time, AdviceMetric::time_to_rest}) {
            const bool landing = m == AdviceMetric::landing_time;
            if (const std::optional<Candidate> c = time_candidate(m, landing ? v.landing_time : v.rest_time,
                                                                  landing ? b.landing_time : b.rest_time, value.end_time,
                                                                  baseline.end_time, i, tol))
                take(m, *c);
        }
        const std::size_t impacts = std::min(v.impact_speeds.size(), b.impact_speeds.size());
        for (std::size_t k = 0; k < impacts; ++k) {
            Candidate c = candidate(AdviceMetric::impact_speed, v.impact_speeds[k], b.impact_speeds[k], false, i, tol);
            c.d.impact = static_cast<int>(k) + 1;
            take(AdviceMetric::impact_speed, c);
        }
        if (v.landing && b.landing)
            take(AdviceMetric::range, candidate(AdviceMetric::range, horizontal_distance(*v.landing, v.start),
                                                horizontal_distance(*b.landing, b.start), false, i, tol));
        take(AdviceMetric::apex_height, candidate(AdviceMetric::apex_height, v.apex_height, b.apex_height, false, i, tol));
        // Landing point, or where a particle that never landed ended up.
        const double moved = glm::length(v.landing.value_or(v.end) - b.landing.value_or(b.end));
        take(AdviceMetric::landing_point, candidate(AdviceMetric::landing_point, moved, 0.0, !v.landing || !b.landing, i, tol));
        out.landing_difference_m = std::max(out.landing_difference_m, moved);
        out.apex_difference_m = std::max(out.apex_difference_m, std::abs(v.apex_height - b.apex_height));
    }
    for (std::size_t k = 0; k < advice_metric_count; ++k) tally[k].finish(out.metrics[k]);
    out.matters = std::any_of(out.metrics.begin(), out.metrics.end(), [](const MetricDelta& d) { return d.beyond_tolerance; });
}

}  // namespace pl
