// The apex and the range at the first impact are measured on each step's own trajectory (step
// replay with a trace), so they converge with the method's order: exact to round-off for the
// methods that are exact on a parabola, and the method's observed order under quadratic drag
// against an independent reference (adaptive Dormand-Prince at a tight tolerance). Sampled at
// step ends, the apex time was off by up to dt / 2 (first order) and the apex height by up to
// g dt^2 / 8; extrapolated linearly, the range was second order at best.
#include "physics/studies/accuracy_study.hpp"
#include "physics/studies/metrics.hpp"
#include "physics/stepping/step_replay.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace pl {
namespace {

constexpr double g = 9.81;

// One ball thrown from 1 m over the floor of a room it cannot reach otherwise (floor at y = 0).
Scene throw_scene(Method method, double dt, DragModel drag) {
    Scene s;
    s.room.center = {0, 50, 0};
    s.room.size = {400, 100, 400};
    s.world.gravity = {0, -g, 0};
    s.drag.model = drag;
    s.contact.restitution = 0.5;
    s.contact.friction = 0.0;
    s.integrator.method = method;
    s.integrator.dt = dt;
    s.integrator.rtol = s.integrator.atol = 1e-12;  // dopri5
    // A light ball (20 g, r = 33 mm): quadratic drag near 0.7 of its weight at launch.
    s.particles = {{{-100, 1.0, 0}, {7.0, 9.0, 2.0}, 0.02, 0.033}};
    return s;
}

ParticleMetrics measure(const Scene& scene, double duration) {
    CompareOptions o;
    o.duration_s = duration;
    o.threads = 1;
    const Comparison c = run_comparison(scene, o);
    EXPECT_TRUE(c.error.empty()) << c.error;
    return c.variants.at(0).particles.at(0);
}

TEST(MetricsFidelity, NoDragApexAndRangeAreExactForMethodsExactOnAParabola) {
    // dt = 0.01 puts the apex (t = vy / g = 0.9174 s) 0.0026 s from the nearest step end.
    const double vx = 7.0, vy = 9.0, vz = 2.0, y0 = 1.0, radius = 0.033;
    const double apex_time = vy / g, apex_height = y0 + vy * vy / (2 * g);
    const double flight = (vy + std::sqrt(vy * vy + 2 * g * (y0 - radius))) / g;  // centre down to y = radius
    for (Method m : {Method::velocity_verlet, Method::rk4, Method::dopri5, Method::exponential}) {
        const ParticleMetrics p = measure(throw_scene(m, 0.01, DragModel::none), 2.5);
        EXPECT_NEAR(p.apex_time, apex_time, 1e-12) << to_string(m);
        EXPECT_NEAR(p.apex_height, apex_height, 1e-12) << to_string(m);
        ASSERT_TRUE(p.range_at_first_impact) << to_string(m);
        EXPECT_NEAR(*p.range_at_first_impact, std::hypot(vx, vz) * flight, 1e-11) << to_string(m);
    }
}

TEST(MetricsFidelity, NoDragEulerApexConvergesAtFirstOrder) {
    // Both Euler steps put their positions on the parabola of a velocity off by g dt / 2: the
    // apex height is off by about vy g dt / (2 g) = vy dt / 2, first order, inside a step or not.
    for (Method m : {Method::explicit_euler, Method::semi_implicit_euler}) {
        std::vector<double> dts, errors;
        for (double dt : {0.02, 0.01, 0.005, 0.0025}) {
            const ParticleMetrics p = measure(throw_scene(m, dt, DragModel::none), 2.5);
            dts.push_back(dt);
            errors.push_back(std::abs(p.apex_height - (1.0 + 81.0 / (2 * g))));
            EXPECT_NEAR(errors.back(), 9.0 * dt / 2, 0.2 * 9.0 * dt / 2) << to_string(m) << " dt " << dt;
        }
        EXPECT_NEAR(*log_log_slope(dts, errors), 1.0, 0.1) << to_string(m);
    }
}

struct Orders {
    double apex_height, apex_time, range;
};

// Observed orders of the apex height, apex time and range at the first impact under quadratic
// drag, against adaptive Dormand-Prince at rtol = atol = 1e-12 (its dense output).
Orders observed_orders(Method method, const std::vector<double>& dts) {
    const double duration = 2.4;  // the ball lands near 1.8 s
    const ParticleMetrics ref = measure(throw_scene(Method::dopri5, 0.01, DragModel::quadratic), duration);
    std::vector<double> height, time, range;
    for (double dt : dts) {
        const ParticleMetrics p = measure(throw_scene(method, dt, DragModel::quadratic), duration);
        height.push_back(std::abs(p.apex_height - ref.apex_height));
        time.push_back(std::abs(p.apex_time - ref.apex_time));
        range.push_back(std::abs(*p.range_at_first_impact - *ref.range_at_first_impact));
    }
    for (double e : height) EXPECT_GT(e, 1e-11) << "at the reference's floor: use coarser steps";
    return {*log_log_slope(dts, height), *log_log_slope(dts, time), *log_log_slope(dts, range)};
}

TEST(MetricsFidelity, QuadraticDragApexAndRangeConvergeWithTheMethodsOrder) {
    const Orders rk4 = observed_orders(Method::rk4, {0.04, 0.02, 0.01, 0.005});
    EXPECT_NEAR(rk4.apex_height, 4.0, 0.4);
    EXPECT_NEAR(rk4.apex_time, 4.0, 0.4);
    EXPECT_NEAR(rk4.range, 4.0, 0.4);
    const Orders verlet = observed_orders(Method::velocity_verlet, {0.01, 0.005, 0.0025, 0.00125});
    EXPECT_NEAR(verlet.apex_height, 2.0, 0.3);
    // The vertex of Verlet's position polynomial misses the apex time by about j q^2 / (2 g), q
    // where the apex falls in its step, which moves with dt: errors below C dt^2 that scatter
    // about the line (measured slope 2.3 here; sampled at step ends it was 1).
    EXPECT_GT(verlet.apex_time, 1.7);
    EXPECT_LT(verlet.apex_time, 3.0);
    EXPECT_NEAR(verlet.range, 2.0, 0.3);
}

TEST(MetricsFidelity, EveryStepReplaysBitForBit) {
    // The trace comes from a replay of the step; it is used only where the replay ends where the
    // simulation did, so a replay that drifted would fall back silently. Every method, with
    // bounces and rests in a small room, on the fast kernel (and spin on the generic one).
    for (Method m : {Method::explicit_euler, Method::semi_implicit_euler, Method::velocity_verlet, Method::rk4,
                     Method::dopri5, Method::exponential}) {
        for (bool spin : {false, true}) {
            Scene s = throw_scene(m, 0.005, DragModel::quadratic);
            s.room = {{0, 1, 0}, {2, 2, 2}};
            s.contact.friction = 0.3;
            s.contact.spin = spin;
            s.integrator.rtol = s.integrator.atol = 1e-6;
            s.particles[0].position = {-0.5, 0.5, 0};
            s.particles[0].velocity = {4, 3, 1};
            Simulation sim(model_for_variant(s, 0), initial_particles(s));
            std::size_t impacts = 0;
            for (int k = 0; k < 600; ++k) {
                StepStart before;
                update_step_start(before, sim, 0);
                sim.step();
                const std::optional<StepTrace> trace = replay_step(sim, 0, before);
                ASSERT_TRUE(trace) << to_string(m) << (spin ? " spin" : "") << " step " << k;
                impacts += trace->impacts.size();
            }
            EXPECT_GT(impacts, 3u) << to_string(m);
        }
    }
}

}  // namespace
}  // namespace pl
