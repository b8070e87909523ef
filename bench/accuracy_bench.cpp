// What accuracy costs (issue 6): on a drag trajectory (the design notes' tennis ball, 57 g,
// r = 33 mm, thrown at (3, 4, 1) m/s from 2 m, quadratic drag, 2 s, no wall reached), the wall
// time adaptive Dormand-Prince needs to end within 1e-6 m and 1e-9 m of a tight reference,
// beside semi-implicit Euler at the default dt and at the dt that reaches 1e-6 m.
// The tolerance (rtol = atol) and the dt are chosen by a short search before timing.
#include "physics/stepping/simulation.hpp"
#include "registry.hpp"

#include <benchmark/benchmark.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <string>

namespace pl::bench {

namespace {

constexpr double duration_s = 2.0;

Model drag_trajectory_model(Method method, double dt, double tol) {
    Model m;
    m.label = "drag trajectory";
    m.room.center = {0.0, 0.0, 0.0};
    m.room.size = {200.0, 200.0, 200.0};  // no wall within 2 s
    m.drag.model = DragModel::quadratic;
    m.drag.cd = 0.47;
    m.integrator.method = method;
    m.integrator.dt = dt;
    m.integrator.rtol = tol;
    m.integrator.atol = tol;
    return m;
}

const ParticleSpec ball{{0.0, 2.0, 0.0}, {3.0, 4.0, 1.0}, 0.057, 0.033};

struct Outcome {
    Vec3 position{0.0};
    std::uint64_t force_evals = 0, steps = 0;
};

Outcome run(Method method, double dt, double tol) {
    Simulation sim(drag_trajectory_model(method, dt, tol), {ball});
    sim.set_threads(1);
    sim.run_until(duration_s);
    return {sim.state().position(0), sim.counters().gravity, sim.step_count()};
}

struct Setting {
    double dt = 0.0, tol = 0.0, error_m = 0.0;
    std::uint64_t force_evals = 0, steps = 0;
};

struct Plan {
    Vec3 reference{0.0};
    Setting dopri_6, dopri_9;  // loosest tolerances reaching 1e-6 m and 1e-9 m
    Setting dopri_grid;        // as the GUI runs it: inside fixed 2 ms steps, rtol = atol = 1e-6
    Setting euler_default;     // semi-implicit Euler at the default dt = 2 ms
    Setting euler_6;           // semi-implicit Euler at the dt that reaches 1e-6 m
};

Setting measure(Method method, double dt, double tol, const Vec3& reference) {
    const Outcome o = run(method, dt, tol);
    return {dt, tol, glm::length(o.position - reference), o.force_evals, o.steps};
}

// Adaptive Dormand-Prince inside a single fixed step as long as the trajectory, so its own
// step-size control alone decides the cost.
Setting loosest_tolerance_for(double target_m, const Vec3& reference) {
    Setting s;
    for (int k = 0; k <= 52; ++k) {
        s = measure(Method::dopri5, duration_s, std::pow(10.0, -2.0 - 0.25 * k), reference);
        if (s.error_m <= target_m) return s;
    }
    return s;
}

const Plan& plan() {
    static const Plan p = [] {
        Plan q;
        // RK4 at 10 us: truncation error ~1e-20 m, far below both targets.
        q.reference = run(Method::rk4, 1e-5, 0.0).position;
        q.dopri_6 = loosest_tolerance_for(1e-6, q.reference);
        q.dopri_9 = loosest_tolerance_for(1e-9, q.reference);
        q.dopri_grid = measure(Method::dopri5, 0.002, 1e-6, q.reference);
        q.euler_default = measure(Method::semi_implicit_euler, 0.002, 0.0, q.reference);
        // First order: the error scales with dt. Aim 10% below the target, then check.
        double dt = 0.002 * 0.9e-6 / q.euler_default.error_m;
        dt = duration_s / std::ceil(duration_s / dt);
        q.euler_6 = measure(Method::semi_implicit_euler, dt, 0.0, q.reference);
        return q;
    }();
    return p;
}

void run_setting(benchmark::State& state, Method method, const Setting& s) {
    for (auto _ : state) {
        const Outcome o = run(method, s.dt, s.tol);
        benchmark::DoNotOptimize(o.position);
    }
    state.counters["error_m"] = s.error_m;
    state.counters["tol"] = s.tol;
    state.counters["dt_s"] = s.dt;
    state.counters["force_evals"] = static_cast<double>(s.force_evals);
    state.counters["steps"] = static_cast<double>(s.steps);
}

void register_setting(const std::string& name, Method method, const Setting& (*pick)()) {
    benchmark::RegisterBenchmark(name.c_str(), [method, pick](benchmark::State& state) {
        run_setting(state, method, pick());
    })->UseRealTime()->Unit(benchmark::kMicrosecond);
}

}  // namespace

void register_accuracy_benchmarks() {
    register_setting("accuracy/dopri5/to:1e-6", Method::dopri5, []() -> const Setting& { return plan().dopri_6; });
    register_setting("accuracy/dopri5/to:1e-9", Method::dopri5, []() -> const Setting& { return plan().dopri_9; });
    register_setting("accuracy/dopri5/dt:2ms", Method::dopri5, []() -> const Setting& { return plan().dopri_grid; });
    register_setting("accuracy/semi_implicit_euler/dt:2ms", Method::semi_implicit_euler,
                     []() -> const Setting& { return plan().euler_default; });
    register_setting("accuracy/semi_implicit_euler/to:1e-6", Method::semi_implicit_euler,
                     []() -> const Setting& { return plan().euler_6; });
}

}  // namespace pl::bench
