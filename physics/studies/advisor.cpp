#include "physics/studies/advisor.hpp"

#include "physics/stepping/contact.hpp"
#include "physics/model/drag.hpp"
#include "physics/stepping/energy.hpp"
#include "physics/stepping/simulation.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace pl {

namespace {

// Advice looks at the first particles only: their trajectories represent the scene, and a
// million-particle emitter would make five extra runs expensive.
constexpr std::size_t max_advice_particles = 100;

std::string metres(double m) {
    const double a = std::abs(m);
    if (a == 0.0) return "0 m";
    if (a < 1e-3) return fmt::format("{:.3g} um", m * 1e6);
    if (a < 1.0) return fmt::format("{:.3g} mm", m * 1e3);
    return fmt::format("{:.4g} m", m);
}

struct Observed {
    ModelRun run;
    double re_min = std::numeric_limits<double>::infinity(), re_max = 0.0;
    double max_drag_to_weight = 0.0, max_mach = 0.0;
    std::vector<Vec3> end_position;  // where particles that never landed ended up
};

// Runs `model` until every particle has hit a floor wall (one that gravity presses toward) or
// the time limit; records landing points, apex heights and the dimensionless numbers.
Observed observe(const Model& model, const std::vector<ParticleSpec>& particles, double max_duration,
                 bool measure_numbers) {
    Observed o;
    o.run.model = model.drag.model;
    o.run.with_wind = model.world.wind.kind != WindKind::none;
    const std::size_t n = particles.size();
    o.run.landing.assign(n, std::nullopt);
    o.run.landing_time.assign(n, 0.0);
    o.run.apex_height.assign(n, 0.0);
    std::uint8_t floor_mask = 0;
    for (int w = 0; w < wall_count; ++w)
        if (glm::dot(model.world.gravity, RoomBounds::inward_normal(w)) < 0.0) floor_mask |= static_cast<std::uint8_t>(1u << w);
    const double floor_y = model.room.floor_y();
    const double g = glm::length(model.world.gravity);

    Simulation sim(model, particles);
    sim.set_threads(1);  // at most max_advice_particles
    std::vector<Vec3> prev_x(n), prev_v(n);
    std::size_t landed = 0;
    for (std::size_t i = 0; i < n; ++i) o.run.apex_height[i] = particles[i].position.y - floor_y;
    const auto max_steps = static_cast<std::uint64_t>(std::ceil(max_duration / sim.dt()));
    for (std::uint64_t k = 0; k < max_steps && landed < n; ++k) {
        const double t0 = sim.time();
        for (std::size_t i = 0; i < n; ++i) {
            prev_x[i] = sim.state().position(i);
            prev_v[i] = sim.state().velocity(i);
            if (!measure_numbers || o.run.landing[i] || sim.state().frozen[i]) continue;
            const Vec3 u = prev_v[i] - sim.wind().at(prev_x[i], t0);
            o.max_mach = std::max(o.max_mach, glm::length(u) / speed_of_sound_mps);
            if (g > 0.0)
                o.max_drag_to_weight =
                    std::max(o.max_drag_to_weight, glm::length(sim.acceleration(i) - model.world.gravity) / g);
        }
        sim.step();
        for (const Event& e : sim.drain_events()) {
            const std::size_t i = e.particle;
            if (o.run.landing[i] || e.wall < 0 || !(floor_mask & (1u << e.wall))) continue;
            if (e.kind != EventKind::bounce && e.kind != EventKind::rest) continue;
            // Linear extrapolation of the state before the step to the impact time (the impact
            // wall's coordinate is exact: the sphere touches it).
            Vec3 at = prev_x[i] + (e.t - t0) * prev_v[i];
            at[RoomBounds::axis(e.wall)] = RoomBounds(model.room).contact_plane(e.wall, particles[i].radius);
            o.run.landing[i] = at;
            o.run.landing_time[i] = e.t;
            ++landed;
        }
        for (std::size_t i = 0; i < n; ++i)
            if (!o.run.landing[i]) o.run.apex_height[i] = std::max(o.run.apex_height[i], sim.state().y[i] - floor_y);
    }
    if (measure_numbers && model.drag.model != DragModel::none) {
        const ReRange seen = sim.observed_reynolds();
        if (seen.hi > 0.0) {
            o.re_min = std::min(o.re_min, seen.lo);
            o.re_max = std::max(o.re_max, seen.hi);
        }
    }
    o.end_position.resize(n);
    for (std::size_t i = 0; i < n; ++i) o.end_position[i] = sim.state().position(i);
    return o;
}

// Landing point, or the final position of a particle that never landed.
Vec3 outcome_point(const Observed& o, std::size_t i) { return o.run.landing[i] ? *o.run.landing[i] : o.end_position[i]; }

void set_differences(Observed& o, const Observed& ref) {
    for (std::size_t i = 0; i < o.run.landing.size(); ++i) {
        o.run.landing_difference_m =
            std::max(o.run.landing_difference_m, glm::length(outcome_point(o, i) - outcome_point(ref, i)));
        o.run.apex_difference_m =
            std::max(o.run.apex_difference_m, std::abs(o.run.apex_height[i] - ref.run.apex_height[i]));
    }
}

double effect(const ModelRun& r) { return std::max(r.landing_difference_m, r.apex_difference_m); }

// The candidate drag models: the variant's own settings for its own model, defaults otherwise
// (Stokes from the air's viscosity for linear; Cd = 0.47 for quadratic unless configured).
DragSettings candidate(DragModel model, const DragSettings& configured) {
    if (model == configured.model) return configured;
    DragSettings d;
    d.model = model;
    if (configured.model == DragModel::quadratic) d.cd = configured.cd;
    return d;
}

VariantAdvice advise_variant(const Model& model, const std::vector<ParticleSpec>& particles, const AdviceOptions& o,
                             const std::function<void()>& tick) {
    VariantAdvice a;
    a.label = model.label;
    a.configured = model.drag.model;
    a.wind = model.world.wind.kind;
    const double tol = o.tolerance_m;

    std::vector<Observed> runs;
    for (DragModel d : {DragModel::none, DragModel::linear, DragModel::quadratic, DragModel::sphere_re}) {
        Model m = model;
        m.drag = candidate(d, model.drag);
        runs.push_back(observe(m, particles, o.max_duration_s, d == DragModel::sphere_re));
        tick();
    }
    const Observed& ref = runs.back();
    for (Observed& r : runs) set_differences(r, ref);
    a.re_min = std::isfinite(ref.re_min) ? ref.re_min : 0.0;
    a.re_max = ref.re_max;
    a.max_drag_to_weight = ref.max_drag_to_weight;
    a.max_mach = ref.max_mach;
    a.stokes_error_factor = sphere_cd_times_re(a.re_max) / 24.0;

    std::optional<Observed> without_wind;
    if (model.world.wind.kind != WindKind::none && model.drag.model != DragModel::none) {
        Model m = model;
        m.world.wind.kind = WindKind::none;
        Model with = model;
        Observed calm = observe(m, particles, o.max_duration_s, false);
        const Observed windy = observe(with, particles, o.max_duration_s, false);
        set_differences(calm, windy);
        without_wind = calm;
    }
    tick();

    for (const Observed& r : runs) a.runs.push_back(r.run);
    a.cheapest_adequate = DragModel::sphere_re;
    for (const Observed& r : runs)
        if (effect(r.run) <= tol) {
            a.cheapest_adequate = r.run.model;
            break;
        }

    const std::string tol_text = metres(tol);
    const ModelRun& none = runs[0].run;
    const ModelRun& linear = runs[1].run;
    const ModelRun& quadratic = runs[2].run;
    const bool landed = std::all_of(ref.run.landing.begin(), ref.run.landing.end(), [](const auto& l) { return l.has_value(); });
    const std::string where = landed ? "the landing point" : fmt::format("the position after {:g} s", o.max_duration_s);

    // Drag as a whole: 'none' against the richest model.
    if (effect(none) <= tol)
        a.verdicts.push_back(fmt::format("drag changes {} by {} and the apex by {}: model 'none' is enough at {} tolerance",
                                         where, metres(none.landing_difference_m), metres(none.apex_difference_m), tol_text));
    else
        a.verdicts.push_back(fmt::format("drag changes {} by {} and the apex by {}: drag is needed at {} tolerance "
                                         "(max drag/weight = {:.3g})",
                                         where, metres(none.landing_difference_m), metres(none.apex_difference_m), tol_text,
                                         a.max_drag_to_weight));
    // Linear (Stokes) drag.
    if (a.re_max > 1.0 && effect(linear) > tol)
        a.verdicts.push_back(fmt::format("Re = {:.2g}: linear drag is wrong here by {:.0f}x (it moves {} by {} against "
                                         "sphere_re), use quadratic or sphere_re",
                                         a.re_max, a.stokes_error_factor, where, metres(linear.landing_difference_m)));
    else if (a.re_max > 1.0)
        a.verdicts.push_back(fmt::format("Re = {:.2g}: linear drag is wrong here by {:.0f}x in force, but it changes {} by only "
                                         "{} against sphere_re: enough at {} tolerance",
                                         a.re_max, a.stokes_error_factor, where, metres(effect(linear)), tol_text));
    else
        a.verdicts.push_back(fmt::format("Re <= {:.2g}: Stokes flow, linear drag is within {} of sphere_re{}", a.re_max,
                                         metres(effect(linear)), effect(linear) <= tol ? " (enough)" : " (not enough)"));
    // Quadratic (constant Cd) drag.
    if (effect(quadratic) <= tol)
        a.verdicts.push_back(fmt::format("quadratic drag (Cd = {:g}) is within {} of sphere_re: enough at {} tolerance",
                                         candidate(DragModel::quadratic, model.drag).cd, metres(effect(quadratic)), tol_text));
    else
        a.verdicts.push_back(fmt::format("quadratic drag (Cd = {:g}) differs from sphere_re by {} over Re = {:.2g} .. {:.2g}: "
                                         "use sphere_re",
                                         candidate(DragModel::quadratic, model.drag).cd, metres(effect(quadratic)),
                                         a.re_min, a.re_max));
    // Wind.
    if (model.world.wind.kind == WindKind::none)
        a.verdicts.push_back("no wind in this scene");
    else if (model.drag.model == DragModel::none)
        a.verdicts.push_back("drag is off, so wind has no effect");
    else if (without_wind) {
        const double d = effect(without_wind->run);
        a.verdicts.push_back(fmt::format("wind ({}) moves {} by {}: {} at {} tolerance", to_string(model.world.wind.kind),
                                         where, metres(d), d <= tol ? "negligible" : "needed", tol_text));
        a.runs.push_back(without_wind->run);
    }
    // Summary against what the variant uses.
    a.verdicts.push_back(fmt::format("cheapest drag model within {} of sphere_re: '{}'; this variant uses '{}'", tol_text,
                                     to_string(a.cheapest_adequate), to_string(model.drag.model)));

    if (a.max_mach > 0.3)
        a.warnings.push_back(fmt::format("Mach {:.2f}: compressibility is not modelled (unreliable above Mach 0.3)", a.max_mach));
    if (model.drag.model != DragModel::none) {
        const ReRange valid = drag_validity(model.drag.model);
        if (a.re_max > 0.0 && (a.re_min < valid.lo || a.re_max > valid.hi))
            a.warnings.push_back(fmt::format("Re = {:.2g} .. {:.2g} leaves the {} model's validity range {:.3g} < Re < {:.3g}",
                                             a.re_min, a.re_max, to_string(model.drag.model), valid.lo, valid.hi));
    }
    return a;
}

}  // namespace

Advice advise(const Scene& scene, const AdviceOptions& o) {
    Advice advice;
    advice.tolerance_m = o.tolerance_m;
    std::vector<ParticleSpec> particles = initial_particles(scene);
    advice.particles_total = particles.size();
    if (particles.size() > max_advice_particles) particles.resize(max_advice_particles);
    advice.particles_used = particles.size();
    const std::size_t variants = variant_count(scene);
    std::size_t done = 0;
    const std::size_t total = variants * 5;
    auto tick = [&] {
        ++done;
        if (o.progress) o.progress(static_cast<double>(done) / static_cast<double>(total));
    };
    for (std::size_t v = 0; v < variants; ++v) {
        if (o.cancel && o.cancel->load(std::memory_order_relaxed)) {
            advice.cancelled = true;
            break;
        }
        advice.variants.push_back(advise_variant(model_for_variant(scene, v), particles, o, tick));
    }
    return advice;
}

}  // namespace pl
