#include "physics/studies/stability_study.hpp"

#include "physics/stepping/contact.hpp"
#include "physics/stepping/energy.hpp"
#include "physics/stepping/simulation.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <map>
#include <thread>

namespace pl {

const char* to_string(StabilityOutcome o) {
    switch (o) {
        case StabilityOutcome::stable: return "stable";
        case StabilityOutcome::energy_growth: return "energy_growth";
        case StabilityOutcome::nan: return "nan";
        case StabilityOutcome::escaped: return "escaped";
        case StabilityOutcome::jitter: return "jitter";
        case StabilityOutcome::tunnelled: return "tunnelled";
        case StabilityOutcome::overlap: return "overlap";
    }
    return "?";
}

StabilityGrid default_stability_grid(bool quick) {
    StabilityGrid g;
    g.methods = {Method::explicit_euler, Method::semi_implicit_euler, Method::velocity_verlet,
                 Method::rk4,            Method::dopri5,              Method::exponential};
    if (quick) {
        g.dts = {1e-4, 1e-3, 1e-2, 0.1};
        g.stiffnesses = {0.0, 10.0, 1000.0};
        g.sweep_dts = {1e-3, 0.05};
        g.speeds = {0.0, 100.0};
        g.restitutions = {0.0, 1.0};
        g.radius_fractions = {0.05, 0.49};
        g.sweep_stiffnesses = {0.0};
        g.pair_dts = {1e-3, 0.05};
        g.pair_speeds = {10.0, 100.0};
        g.pair_restitutions = {0.0, 1.0};
        g.pair_radius_ratios = {1.0, 10.0};
        g.pair_mass_ratios = {1e-3, 1e3};
        g.limits.max_steps = 1000;
        return g;
    }
    // 1-2-5 per decade from 1e-5 to 0.5 s.
    for (double decade = 1e-5; decade < 1.0; decade *= 10.0)
        for (double m : {1.0, 2.0, 5.0})
            if (m * decade <= 0.5 * (1.0 + 1e-12)) g.dts.push_back(m * decade);
    g.stiffnesses = {0.0, 1.0, 10.0, 100.0, 1e3, 1e4};
    g.sweep_dts = {1e-4, 1e-3, 1e-2, 0.1, 0.5};
    g.speeds = {0.0, 1.0, 10.0, 100.0, 1000.0};
    g.restitutions = {0.0, 0.5, 1.0};
    g.radius_fractions = {0.01, 0.25, 0.49};
    g.sweep_stiffnesses = {0.0, 100.0};
    g.pair_dts = {1e-4, 1e-3, 1e-2, 0.05};
    g.pair_speeds = {1.0, 10.0, 100.0};
    g.pair_restitutions = {0.0, 0.5, 1.0};
    g.pair_radius_ratios = {1.0, 10.0};
    g.pair_mass_ratios = {1e-3, 1.0, 1e3};
    return g;
}

StabilityBase default_stability_base() {
    StabilityBase b;
    b.room.center = Vec3(0.0);
    b.room.size = Vec3(2.0);
    return b;
}

StabilityBase stability_base(const Scene& scene) {
    StabilityBase b;
    b.room = scene.room;
    b.gravity = scene.world.gravity;
    b.contact = scene.contact;
    const std::vector<ParticleSpec> particles = scene.particles.empty() ? initial_particles(scene) : scene.particles;
    if (!particles.empty()) b.mass = particles.front().mass;
    return b;
}

Vec3 stability_launch_direction() { return glm::normalize(Vec3(1.0, 1.0, 0.5)); }

Model stability_model(const StabilityBase& base, const StabilityCase& c, const char* label) {
    Model m;
    m.label = label;
    m.room = base.room;
    m.world.gravity = base.gravity;
    m.contact = base.contact;
    m.contact.restitution = c.restitution;
    m.integrator.method = c.method;
    m.integrator.dt = c.dt;
    return m;
}

std::uint64_t stability_steps(const StabilityCase& c, const StabilityRunLimits& limits) {
    const double wanted = std::ceil(limits.max_duration_s / c.dt);
    return static_cast<std::uint64_t>(
        std::clamp(wanted, static_cast<double>(limits.min_steps), static_cast<double>(limits.max_steps)));
}

std::optional<WallOutcome> wall_outcome(const Room& room, const Vec3& x, double radius, double t, const std::string& what) {
    const RoomBounds bounds(room);
    const double slack = 1e-9 * std::max({room.size.x, room.size.y, room.size.z});
    for (int w = 0; w < wall_count; ++w) {
        const double d = bounds.distance(w, x, radius);
        if (d + radius < -slack)
            return WallOutcome{StabilityOutcome::tunnelled,
                               fmt::format("t = {:.6g} s: {}'s centre {:.3g} m beyond wall {}", t, what, -(d + radius), wall_name(w))};
        if (d < -slack)
            return WallOutcome{StabilityOutcome::escaped, fmt::format("t = {:.6g} s: {} {:.3g} m into wall {}", t, what, -d, wall_name(w))};
    }
    return std::nullopt;
}

std::optional<std::string> energy_grown(StabilityCell& cell, double energy, double e0, double scale, double t) {
    cell.max_energy_ratio = std::max(cell.max_energy_ratio, e0 > 0.0 ? energy / e0 : 1.0);
    if (energy > e0 + stability_energy_tolerance * scale)
        return fmt::format("t = {:.6g} s: KE + PE = {:.4g} J, E0 = {:.4g} J", t, energy, e0);
    return std::nullopt;
}

StabilityCell finish_cell(StabilityCell cell, const Simulation& sim, StabilityOutcome o, std::string detail) {
    cell.outcome = o;
    cell.detail = std::move(detail);
    cell.steps = sim.step_count();
    cell.simulated_s = sim.time();
    return cell;
}

namespace {

// Upper bound on the time a particle launched with `speed` from height `height` over the floor
// needs to stop bouncing without drag: the first fall (at most (v + v1)/g, v1 the largest
// possible impact speed) plus the bounce series sum_{n>=1} 2 v1 e^n / g = 2 v1 e / (g (1-e)),
// doubled for safety (friction on side-wall impacts can slow a descent).
double time_to_rest_bound(double speed, double height, double g, double e) {
    const double v1 = std::sqrt(speed * speed + 2.0 * g * std::max(height, 0.0));
    return 2.0 * ((speed + v1) / g + 2.0 * v1 * e / (g * (1.0 - e)));
}

}  // namespace

StabilityCell classify_stability(const StabilityBase& base, const StabilityCase& c, const StabilityRunLimits& limits) {
    if (c.pair()) return classify_pair(base, c, limits);
    StabilityCell cell;
    cell.c = c;
    const double min_size = std::min({base.room.size.x, base.room.size.y, base.room.size.z});
    ParticleSpec p;
    p.mass = base.mass;
    p.radius = c.radius_fraction * min_size;
    p.position = base.room.center;
    p.velocity = c.speed * stability_launch_direction();

    Model m = stability_model(base, c, "stability");
    if (c.stiffness > 0.0) {
        m.drag.model = DragModel::linear;
        m.drag.linear_b = c.stiffness * base.mass;
    }

    const double g = glm::length(base.gravity);
    const double e0 = kinetic_energy(p.mass, p.velocity) + potential_energy(base.gravity, base.room, p.mass, p.position);
    const double energy_scale = std::max(e0, p.mass * g * 1e-3);
    std::uint64_t steps = stability_steps(c, limits);

    // Floor walls: those gravity presses a particle against.
    std::uint8_t floor_mask = 0;
    for (int w = 0; w < wall_count; ++w)
        if (glm::dot(base.gravity, RoomBounds::inward_normal(w)) < 0.0) floor_mask |= static_cast<std::uint8_t>(1u << w);
    const double height = g > 0.0 ? potential_energy(base.gravity, base.room, 1.0, p.position) / g - p.radius : 0.0;
    double rest_bound = std::numeric_limits<double>::infinity();
    if (c.restitution < 1.0 && g > 0.0) {
        rest_bound = time_to_rest_bound(c.speed, height, g, c.restitution) + 20.0 * c.dt;
        // With drag the fall can be slower than in vacuum; only check when drag is weak over the bound.
        if (c.stiffness * rest_bound > 0.1) rest_bound = std::numeric_limits<double>::infinity();
    }
    // The jitter check begins at the time-to-rest bound: a run shorter than it could not see a
    // ball that never rests (explicit Euler's rest trap, no_rest_dt), so it is lengthened to
    // pass the bound by a quarter of it, where bounces are looked for, up to rest_steps_factor
    // times max_steps.
    const double steps_to_bound = std::floor(1.25 * rest_bound / c.dt) + 2.0;
    if (static_cast<double>(steps) * c.dt <= rest_bound &&
        steps_to_bound <= static_cast<double>(limits.max_steps * StabilityRunLimits::rest_steps_factor))
        steps = static_cast<std::uint64_t>(steps_to_bound);
    cell.jitter_checked = static_cast<double>(steps) * c.dt > rest_bound;

    Simulation sim(m, {p});
    sim.set_threads(1);  // cells already run in parallel
    cell.max_energy_ratio = 1.0;
    auto finish = [&](StabilityOutcome o, std::string detail) { return finish_cell(cell, sim, o, std::move(detail)); };
    for (std::uint64_t k = 0; k < steps; ++k) {
        sim.step();
        const ParticleState& s = sim.state();
        if (s.frozen[0]) return finish(StabilityOutcome::nan, fmt::format("t = {:.6g} s: state became non-finite", sim.time()));
        const Vec3 x = s.position(0), v = s.velocity(0);
        if (std::optional<WallOutcome> w = wall_outcome(base.room, x, p.radius, sim.time(), "sphere"))
            return finish(w->outcome, std::move(w->detail));
        const double energy = kinetic_energy(p.mass, v) + potential_energy(base.gravity, base.room, p.mass, x);
        if (std::optional<std::string> grown = energy_grown(cell, energy, e0, energy_scale, sim.time()))
            return finish(StabilityOutcome::energy_growth, std::move(*grown));
    }
    if (cell.jitter_checked) {
        for (const Event& e : sim.events()) {
            if (e.t > rest_bound && e.kind == EventKind::bounce && e.wall >= 0 && (floor_mask & (1u << e.wall)))
                return finish(StabilityOutcome::jitter,
                              fmt::format("t = {:.6g} s: still bouncing on {} (speed {:.3g} m/s) after the "
                                          "time-to-rest bound {:.3g} s",
                                          e.t, wall_name(e.wall), e.speed_in, rest_bound));
        }
    } else {
        // Too long a run to reach the bound: the engine's own warning of the rest trap, raised
        // at the first bounce on a floor, still tells.
        for (const Warning& w : sim.warnings())
            if (w.kind == WarningKind::no_rest)
                return finish(StabilityOutcome::jitter,
                              fmt::format("t = {:.6g} s: bouncing on a floor with explicit Euler at dt > "
                                          "rest_speed (1 - e) / (e g) = {:.3g} s, it can never rest",
                                          w.t, w.value));
    }
    return finish(StabilityOutcome::stable, "");
}

namespace {

// Classifies every case on `threads` workers; results land in case order, so they do not
// depend on the thread count.
std::vector<StabilityCell> classify_all(const StabilityBase& base, const std::vector<StabilityCase>& cases,
                                        const StabilityOptions& options, std::size_t done_before, std::size_t total,
                                        bool& cancelled) {
    std::vector<StabilityCell> cells(cases.size());
    std::atomic<std::size_t> next{0}, done{0};
    std::atomic<bool> stop{false};
    auto worker = [&] {
        for (;;) {
            if (options.cancel && options.cancel->load(std::memory_order_relaxed)) {
                stop = true;
                return;
            }
            const std::size_t i = next.fetch_add(1);
            if (i >= cases.size()) return;
            cells[i] = classify_stability(base, cases[i], options.grid.limits);
            const std::size_t d = done.fetch_add(1) + 1;
            if (options.progress)
                options.progress(static_cast<double>(done_before + d) / static_cast<double>(std::max<std::size_t>(total, 1)));
        }
    };
    unsigned n = options.threads ? options.threads : std::max(1u, std::thread::hardware_concurrency());
    n = static_cast<unsigned>(std::min<std::size_t>(n, std::max<std::size_t>(cases.size(), 1)));
    std::vector<std::thread> pool;
    for (unsigned t = 1; t < n; ++t) pool.emplace_back(worker);
    worker();
    for (std::thread& t : pool) t.join();
    if (stop) {  // unfinished cells would read as default ones: return none
        cancelled = true;
        cells.clear();
    }
    return cells;
}

std::vector<StabilityCase> map_cases(Method method, const std::vector<double>& dts, const std::vector<double>& ks,
                                     double speed, double restitution, double radius_fraction) {
    std::vector<StabilityCase> cases;
    for (double dt : dts)
        for (double k : ks) cases.push_back({method, dt, k, speed, restitution, radius_fraction});
    return cases;
}

}  // namespace

std::vector<StabilityCell> stability_map(const StabilityBase& base, Method method, const std::vector<double>& dts,
                                         const std::vector<double>& stiffnesses, double speed, double restitution,
                                         double radius_fraction, const StabilityOptions& options) {
    const std::vector<StabilityCase> cases = map_cases(method, dts, stiffnesses, speed, restitution, radius_fraction);
    bool cancelled = false;
    return classify_all(base, cases, options, 0, cases.size(), cancelled);
}

std::vector<StabilityLimit> stability_limits(const std::vector<StabilityCell>& map_cells) {
    std::map<std::pair<int, double>, std::vector<const StabilityCell*>> groups;
    for (const StabilityCell& c : map_cells) groups[{static_cast<int>(c.c.method), c.c.stiffness}].push_back(&c);
    std::vector<StabilityLimit> out;
    for (auto& [key, cells] : groups) {
        std::sort(cells.begin(), cells.end(), [](const StabilityCell* a, const StabilityCell* b) { return a->c.dt < b->c.dt; });
        StabilityLimit l;
        l.method = static_cast<Method>(key.first);
        l.stiffness = key.second;
        const double limit = method_stability_limit(l.method);
        l.theoretical_dt = l.stiffness > 0.0 ? limit / l.stiffness : std::numeric_limits<double>::infinity();
        for (const StabilityCell* c : cells) {
            if (c->outcome != StabilityOutcome::stable) {
                l.first_unstable_dt = c->c.dt;
                break;
            }
            l.measured_dt = c->c.dt;
        }
        out.push_back(l);
    }
    return out;
}

StabilityReport run_stability_study(const StabilityBase& base, const StabilityOptions& options) {
    const StabilityGrid& g = options.grid;
    std::vector<StabilityCase> map, sweep, pairs;
    for (Method method : g.methods) {
        for (double dt : g.pair_dts)
            for (double speed : g.pair_speeds)
                for (double e : g.pair_restitutions)
                    for (double radii : g.pair_radius_ratios)
                        for (double masses : g.pair_mass_ratios)
                            pairs.push_back({method, dt, 0.0, speed, e, g.pair_radius_fraction, radii, masses});
        std::vector<StabilityCase> m =
            map_cases(method, g.dts, g.stiffnesses, g.map_speed, g.map_restitution, g.map_radius_fraction);
        map.insert(map.end(), m.begin(), m.end());
        for (double k : g.sweep_stiffnesses)
            for (double dt : g.sweep_dts)
                for (double speed : g.speeds)
                    for (double e : g.restitutions)
                        for (double r : g.radius_fractions) sweep.push_back({method, dt, k, speed, e, r});
    }
    StabilityReport report;
    const std::size_t total = map.size() + sweep.size() + pairs.size();
    report.map_cells = classify_all(base, map, options, 0, total, report.cancelled);
    if (!report.cancelled) report.sweep_cells = classify_all(base, sweep, options, map.size(), total, report.cancelled);
    if (!report.cancelled)
        report.pair_cells = classify_all(base, pairs, options, map.size() + sweep.size(), total, report.cancelled);
    report.limits = stability_limits(report.map_cells);
    return report;
}

}  // namespace pl
