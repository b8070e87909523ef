#include "physics/studies/accuracy_study.hpp"

#include "physics/model/drag.hpp"
#include "physics/stepping/simulation.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

namespace pl {

namespace {

const std::vector<Method> all_methods = {Method::explicit_euler, Method::semi_implicit_euler, Method::velocity_verlet,
                                         Method::rk4,            Method::dopri5,              Method::exponential};

struct RunResult {
    Vec3 x{0.0}, v{0.0};
    std::vector<Event> impacts;
    std::uint64_t steps = 0, force_evaluations = 0;
    double wall_seconds_per_sim_second = 0.0;
};

std::vector<Event> impacts_of(const std::vector<Event>& events) {
    std::vector<Event> out;
    for (const Event& e : events)
        if (e.wall >= 0 && (e.kind == EventKind::bounce || e.kind == EventKind::rest)) out.push_back(e);
    return out;
}

// Runs one configuration; repeats it (results identical) until the timing means something,
// since a single particle runs in microseconds, and keeps the fastest run (the least disturbed
// by other processes).
RunResult run_once(const Model& model, const ParticleSpec& particle, std::uint64_t steps) {
    using clock = std::chrono::steady_clock;
    RunResult r;
    double total = 0.0, fastest = INFINITY;
    int repeats = 0;
    do {
        Simulation sim(model, {particle});
        sim.set_threads(1);  // one particle
        const auto start = clock::now();
        sim.step_n(steps);
        const double seconds = std::chrono::duration<double>(clock::now() - start).count();
        total += seconds;
        fastest = std::min(fastest, seconds);
        if (repeats++ == 0) {
            r.x = sim.state().position(0);
            r.v = sim.state().velocity(0);
            r.impacts = impacts_of(sim.events());
            const ForceCounters& c = sim.counters();
            r.force_evaluations = c.gravity;
            r.steps = model.integrator.method == Method::dopri5 && model.integrator.adaptive
                          ? c.accepted_steps + c.rejected_steps
                          : sim.step_count();
        }
    } while (total < 2e-3 && repeats < 50);
    r.wall_seconds_per_sim_second = fastest / (static_cast<double>(steps) * model.integrator.dt);
    return r;
}

// Closed forms without wall contact: free flight, and linear drag in still or constant wind
// (a = g - k (v - w): v(t) = v_inf + (v0 - v_inf) e^{-kt}, v_inf = w + g / k).
std::optional<std::pair<Vec3, Vec3>> closed_form(const Model& m, const ParticleSpec& p, double t, std::string& name) {
    const Vec3 g = m.world.gravity;
    if (m.drag.model == DragModel::none) {
        name = "closed form (free flight, no wall contact)";
        return std::make_pair(p.position + p.velocity * t + 0.5 * g * t * t, p.velocity + g * t);
    }
    const WindKind wind = m.world.wind.kind;
    if (m.drag.model == DragModel::linear && (wind == WindKind::none || wind == WindKind::constant)) {
        const double k = drag_coefficients(m.drag, m.world.air, p.mass, p.radius).k;
        if (!(k > 0.0)) return std::nullopt;
        const Vec3 w = wind == WindKind::constant ? m.world.wind.velocity : Vec3(0.0);
        const Vec3 v_inf = w + g / k;
        const double decay = std::exp(-k * t);
        name = "closed form (linear drag, no wall contact)";
        return std::make_pair(p.position + v_inf * t + (p.velocity - v_inf) * (-std::expm1(-k * t) / k),
                              v_inf + (p.velocity - v_inf) * decay);
    }
    return std::nullopt;
}

// Steps of `dt` that make up `duration`, or 0 when dt does not divide it.
std::uint64_t steps_for(double duration, double dt) {
    const double n = duration / dt;
    if (std::abs(n - std::round(n)) > 1e-6 * std::max(1.0, n)) return 0;
    return static_cast<std::uint64_t>(std::llround(n));
}

void compare(AccuracyRow& row, const RunResult& run, const RunResult& ref) {
    row.steps = run.steps;
    row.force_evaluations = run.force_evaluations;
    row.wall_seconds_per_sim_second = run.wall_seconds_per_sim_second;
    row.position_error = glm::length(run.x - ref.x);
    row.velocity_error = glm::length(run.v - ref.v);
    row.impacts = run.impacts.size();
    double worst = 0.0;
    std::size_t matched = 0;
    for (; matched < std::min(run.impacts.size(), ref.impacts.size()); ++matched) {
        if (run.impacts[matched].wall != ref.impacts[matched].wall) break;
        worst = std::max(worst, std::abs(run.impacts[matched].t - ref.impacts[matched].t));
    }
    row.impacts_matched = matched;
    if (matched > 0) row.bounce_time_error = worst;
}

// The fixed-step rows' order: a fit through the rows clearly above the floor, when there are enough.
MethodOrder fit_order(Method method, const std::vector<AccuracyRow>& rows) {
    MethodOrder mo;
    mo.method = method;
    mo.expected = method_order(method);
    std::vector<double> dts, errors;
    for (const AccuracyRow& row : rows) {
        if (row.method != method || row.adaptive) continue;
        ++mo.rows;
        if (!(row.position_error >= order_floor_margin * row.error_floor)) continue;
        dts.push_back(row.dt);
        errors.push_back(row.position_error);
    }
    mo.points = dts.size();
    mo.too_few_points = mo.points < min_order_points;
    if (!mo.too_few_points) mo.observed = log_log_slope(dts, errors);
    return mo;
}

}  // namespace

std::string MethodOrder::note() const {
    if (!too_few_points) return {};
    return fmt::format("too few points above the floor ({} of {}, {} needed)", points, rows, min_order_points);
}

std::optional<double> log_log_slope(const std::vector<double>& x, const std::vector<double>& y) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < std::min(x.size(), y.size()); ++i) {
        if (!(x[i] > 0.0) || !(y[i] > 0.0) || !std::isfinite(x[i]) || !std::isfinite(y[i])) continue;
        const double lx = std::log(x[i]), ly = std::log(y[i]);
        sx += lx;
        sy += ly;
        sxx += lx * lx;
        sxy += lx * ly;
        ++n;
    }
    if (n < 2) return std::nullopt;
    const double denom = static_cast<double>(n) * sxx - sx * sx;
    if (denom <= 0.0) return std::nullopt;
    return (static_cast<double>(n) * sxy - sx * sy) / denom;
}

AccuracyReport run_accuracy_study(const Scene& scene, const AccuracyOptions& o) {
    AccuracyReport report;
    report.particle = o.particle;
    const std::vector<ParticleSpec> particles = initial_particles(scene);
    if (o.variant >= variant_count(scene)) {
        report.error = fmt::format("--variant: must be < {} (the number of variants), got {}", variant_count(scene), o.variant);
        return report;
    }
    if (o.particle >= particles.size()) {
        report.error = fmt::format("--particle: must be < {} (the number of particles), got {}", particles.size(), o.particle);
        return report;
    }
    if (!(o.duration_s > 0.0) || !std::isfinite(o.duration_s)) {
        report.error = fmt::format("--duration: must be a finite number > 0, got {}", o.duration_s);
        return report;
    }
    const Model base = model_for_variant(scene, o.variant);
    report.variant_label = base.label;
    const ParticleSpec particle = particles[o.particle];

    std::vector<double> dts = o.dts;
    if (dts.empty())
        for (int i = 0; i < 5; ++i) dts.push_back(base.integrator.dt * 4.0 / std::pow(2.0, i));
    for (std::size_t i = 0; i < dts.size(); ++i)
        if (!(dts[i] > 0.0) || !std::isfinite(dts[i])) {
            report.error = fmt::format("--dt: every step must be a finite number > 0, got {}", dts[i]);
            return report;
        }
    std::vector<double> tolerances = o.tolerances;
    if (tolerances.empty())
        for (int e = 3; e <= 9; ++e) tolerances.push_back(std::pow(10.0, -e));
    for (double tol : tolerances)
        if (!(tol > 0.0 && tol < 1.0)) {
            report.error = fmt::format("--tol: every tolerance must be in (0, 1), got {}", tol);
            return report;
        }
    const std::vector<Method>& methods = o.methods.empty() ? all_methods : o.methods;

    // The end time: the duration rounded up to a whole number of the largest step.
    const double dt_max = *std::max_element(dts.begin(), dts.end());
    const double duration = std::ceil(o.duration_s / dt_max * (1.0 - 1e-12)) * dt_max;
    report.duration_s = duration;
    for (double dt : dts)
        if (steps_for(duration, dt) == 0) {
            report.error = fmt::format("--dt: {} s does not divide the duration {} s (the requested duration "
                                       "rounded up to a whole number of the largest step); use steps that divide each other",
                                       dt, duration);
            return report;
        }
    // The adaptive runs' outer step (AccuracyOptions::adaptive_outer_dt_s): a whole number of
    // them fills the duration.
    std::uint64_t outer_steps = 1;
    double outer_dt = duration;
    auto set_outer = [&](double wanted) {
        outer_steps = static_cast<std::uint64_t>(std::max(1.0, std::ceil(duration / wanted * (1.0 - 1e-12))));
        outer_dt = duration / static_cast<double>(outer_steps);
    };
    set_outer(o.adaptive_outer_dt_s > 0.0 ? o.adaptive_outer_dt_s : duration);

    std::size_t total = 1, done = 0;
    for (Method m : methods)
        total += (m == Method::dopri5 && !o.dopri5_fixed_step) ? tolerances.size() : dts.size();
    auto tick = [&] {
        ++done;
        if (o.progress) o.progress(static_cast<double>(done) / static_cast<double>(total));
    };
    auto cancelled = [&] { return o.cancel && o.cancel->load(std::memory_order_relaxed); };

    // Reference: adaptive Dormand-Prince at a tight tolerance, with event location; replaced by
    // the closed form when the scene has one and the particle touches no wall.
    Model ref_model = base;
    ref_model.integrator.method = Method::dopri5;
    ref_model.integrator.adaptive = true;
    ref_model.integrator.rtol = ref_model.integrator.atol = o.reference_tolerance;
    ref_model.integrator.dt = outer_dt;
    RunResult ref = run_once(ref_model, particle, outer_steps);
    if (!ref.impacts.empty() && o.adaptive_outer_dt_s <= 0.0 && outer_dt > base.integrator.dt) {
        // Walls reached: rest is decided per outer step (a rebound whose whole series of bounces
        // would end within the step rests), so one outer step as long as the run would let a
        // bouncing ball rest at once. The adaptive runs take the scene's own dt as outer step.
        set_outer(base.integrator.dt);
        ref_model.integrator.dt = outer_dt;
        ref = run_once(ref_model, particle, outer_steps);
    }
    report.reference_impacts = ref.impacts.size();
    report.reference = fmt::format("dopri5 adaptive, rtol = atol = {:g}", o.reference_tolerance);
    double reference_error = 0.0;  // m
    std::string name;
    const auto exact = ref.impacts.empty() ? closed_form(base, particle, duration, name) : std::nullopt;
    if (exact) {
        ref.x = exact->first;
        ref.v = exact->second;
        report.reference = name;
    } else {
        // The reference's error, from a second reference at 10x its tolerance (file comment).
        Model looser = ref_model;
        looser.integrator.rtol = looser.integrator.atol = std::min(0.1, 10.0 * o.reference_tolerance);
        reference_error = 0.1 * glm::length(run_once(looser, particle, outer_steps).x - ref.x);
    }
    report.reference_error = reference_error;
    // Round-off per step of a run (file comment).
    const double round_off_per_step = std::numeric_limits<double>::epsilon() * (1.0 + glm::length(ref.x));
    tick();

    for (Method method : methods) {
        const bool over_tolerances = method == Method::dopri5 && !o.dopri5_fixed_step;
        for (std::size_t i = 0; i < (over_tolerances ? tolerances.size() : dts.size()); ++i) {
            if (cancelled()) {
                report.cancelled = true;
                return report;
            }
            Model m = base;
            m.integrator.method = method;
            AccuracyRow row;
            row.method = method;
            std::uint64_t steps;
            if (over_tolerances) {
                m.integrator.adaptive = true;
                m.integrator.rtol = m.integrator.atol = tolerances[i];
                m.integrator.dt = outer_dt;
                row.adaptive = true;
                row.tolerance = tolerances[i];
                row.dt = outer_dt;
                steps = outer_steps;
            } else {
                m.integrator.adaptive = false;
                m.integrator.dt = dts[i];
                row.dt = dts[i];
                steps = steps_for(duration, dts[i]);
            }
            compare(row, run_once(m, particle, steps), ref);
            row.error_floor = reference_error + static_cast<double>(row.steps) * round_off_per_step;
            report.rows.push_back(row);
            tick();
        }
        if (!over_tolerances) report.orders.push_back(fit_order(method, report.rows));
    }
    return report;
}

}  // namespace pl
