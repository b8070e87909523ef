// Comparison metrics against closed forms, the physical ordering of drag models, and the
// lockstep/duration rules the CLI relies on.
#include "physics/studies/metrics.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace pl {
namespace {

constexpr double g = 9.81;

CompareOptions lasting(double seconds) {
    CompareOptions o;
    o.duration_s = seconds;
    return o;
}

DragSettings drag(DragModel model) {
    DragSettings d;
    d.model = model;
    return d;
}

// One particle thrown in a big room (floor at y = 0), no variants.
Scene throw_scene(Vec3 velocity, Method method, double dt, double mass = 0.057, double radius = 0.033) {
    Scene s;
    s.room.center = {0, 50, 0};
    s.room.size = {400, 100, 400};
    s.contact.restitution = 0.5;
    s.contact.friction = 0.0;
    s.integrator.method = method;
    s.integrator.dt = dt;
    s.particles = {{{-100, 1.0 + radius, 0}, velocity, mass, radius}};
    return s;
}

TEST(Metrics, NoDragApexRangeAndFlightTimeMatchTheClosedForm) {
    // Velocity Verlet is exact for constant gravity, so the only differences left are the apex
    // sampled at the step grid (below g dt^2 / 2) and round-off.
    const double dt = 1e-3, vx = 7.0, vy = 9.0, h0 = 1.0;
    const Scene scene = throw_scene({vx, vy, 0}, Method::velocity_verlet, dt);
    const Comparison c = run_comparison(scene, lasting(3.0));
    ASSERT_TRUE(c.error.empty()) << c.error;
    ASSERT_EQ(c.variants.size(), 1u);
    const ParticleMetrics& p = c.variants[0].particles[0];
    const double radius = scene.particles[0].radius;
    const double apex = h0 + radius + vy * vy / (2 * g);  // centre height over the floor
    EXPECT_NEAR(p.apex_height, apex, 0.5 * g * dt * dt);
    EXPECT_LE(p.apex_height, apex + 1e-12);
    EXPECT_NEAR(p.apex_time, vy / g, dt);
    const double flight = (vy + std::sqrt(vy * vy + 2 * g * h0)) / g;  // centre falls to y = radius
    ASSERT_TRUE(p.first_impact_time);
    EXPECT_NEAR(*p.first_impact_time, flight, 1e-9);
    EXPECT_EQ(p.first_impact_wall, static_cast<int>(Wall::y_min));
    ASSERT_TRUE(p.range_at_first_impact);
    EXPECT_NEAR(*p.range_at_first_impact, vx * flight, 1e-8);
}

TEST(Metrics, DropBouncesAndTimeToRestMatchTheClosedForm) {
    // Drop from height h with restitution e: impact speeds v1 e^n at t_n = t0 (1 + 2 (e + ... + e^n));
    // it rests at the first impact whose rebound e v falls below rest_speed.
    const double e = 0.8, h = 2.0, rest_speed = 0.05, dt = 1e-3;
    Scene scene = throw_scene({0, 0, 0}, Method::velocity_verlet, dt);
    scene.particles[0].position.y = h + scene.particles[0].radius;
    scene.contact.restitution = e;
    scene.contact.rest_speed = rest_speed;
    const Comparison c = run_comparison(scene, lasting(8.0));
    ASSERT_TRUE(c.error.empty()) << c.error;
    const ParticleMetrics& p = c.variants[0].particles[0];

    const double t0 = std::sqrt(2 * h / g), v1 = g * t0;
    std::size_t bounces = 0;
    double t = t0, v = v1;
    while (e * v >= rest_speed) {  // this impact rebounds
        ++bounces;
        t += 2 * e * v / g;
        v *= e;
    }
    EXPECT_EQ(p.bounces, bounces);
    ASSERT_TRUE(p.time_to_rest);
    EXPECT_NEAR(*p.time_to_rest, t, 1e-6);
    ASSERT_TRUE(c.variants[0].all_at_rest_time);
    EXPECT_EQ(*c.variants[0].all_at_rest_time, *p.time_to_rest);
    EXPECT_NEAR(*p.first_impact_time, t0, 1e-9);
    EXPECT_EQ(p.final_range, 0.0);
    // Energy lost to bounces: everything above the resting height.
    const double mass = scene.particles[0].mass;
    EXPECT_NEAR(c.variants[0].lost_bounce, mass * g * h, 1e-6);
    EXPECT_GT(c.variants[0].steps, 0u);
    EXPECT_GT(c.variants[0].cost(), 0.0);
}

TEST(Metrics, ApexAndRangeFallAsDragGrows) {
    // A ping-pong-like ball (2.7 g, r = 20 mm) thrown at 20 m/s: drag is several times its weight.
    Scene scene = throw_scene({14, 14, 0}, Method::rk4, 1e-3, 0.0027, 0.02);
    scene.variants = {{"none", drag(DragModel::none), {}, {}, {}, {}, {}},
                      {"linear", drag(DragModel::linear), {}, {}, {}, {}, {}},
                      {"quadratic", drag(DragModel::quadratic), {}, {}, {}, {}, {}}};
    const Comparison c = run_comparison(scene, lasting(4.0));
    ASSERT_TRUE(c.error.empty()) << c.error;
    ASSERT_EQ(c.variants.size(), 3u);
    const ParticleMetrics& none = c.variants[0].particles[0];
    const ParticleMetrics& linear = c.variants[1].particles[0];
    const ParticleMetrics& quadratic = c.variants[2].particles[0];
    EXPECT_GT(none.apex_height, linear.apex_height);
    EXPECT_GT(linear.apex_height, quadratic.apex_height);
    ASSERT_TRUE(none.range_at_first_impact && linear.range_at_first_impact && quadratic.range_at_first_impact);
    EXPECT_GT(*none.range_at_first_impact, *linear.range_at_first_impact);
    EXPECT_GT(*linear.range_at_first_impact, *quadratic.range_at_first_impact);
    EXPECT_EQ(c.variants[0].lost_drag, 0.0);
    EXPECT_GT(c.variants[1].lost_drag, 0.0);
    EXPECT_GT(c.variants[2].lost_drag, c.variants[1].lost_drag);

    const MetricsDifference d = metrics_difference(c.variants[2], c.variants[0], 0);
    EXPECT_DOUBLE_EQ(d.apex_height, quadratic.apex_height - none.apex_height);
    ASSERT_TRUE(d.range_at_first_impact);
    EXPECT_DOUBLE_EQ(*d.range_at_first_impact, *quadratic.range_at_first_impact - *none.range_at_first_impact);
    EXPECT_FALSE(d.time_to_rest);  // neither is at rest after 4 s
}

TEST(Metrics, TrackerFedStepByStepMatchesTheComparisonRun) {
    const Scene scene = throw_scene({3, 5, 1}, Method::semi_implicit_euler, 2e-3);
    const Comparison c = run_comparison(scene, lasting(2.0));
    Simulation sim(model_for_variant(scene, 0), initial_particles(scene));
    MetricsTracker tracker = start_metrics(sim);
    for (int k = 0; k < 1000; ++k) {
        sim.step();
        observe_step(tracker, sim, sim.drain_events(), 0.0);
    }
    const VariantMetrics live = metrics_of(tracker, sim);
    const ParticleMetrics &a = live.particles[0], &b = c.variants[0].particles[0];
    EXPECT_EQ(a.apex_height, b.apex_height);
    EXPECT_EQ(a.first_impact_time, b.first_impact_time);
    EXPECT_EQ(a.range_at_first_impact, b.range_at_first_impact);
    EXPECT_EQ(a.bounces, b.bounces);
    EXPECT_EQ(a.final_range, b.final_range);
}

TEST(Metrics, DurationMustBeAWholeNumberOfEveryVariantsStep) {
    Scene scene = throw_scene({1, 1, 0}, Method::semi_implicit_euler, 0.002);
    IntegratorSettings coarse = scene.integrator;
    coarse.dt = 0.003;
    scene.variants = {{"fine", {}, {}, {}, {}, {}, {}}, {"coarse", {}, {}, {}, {}, coarse, {}}};
    const DurationPlan ok = plan_duration(scene, 0.6);
    EXPECT_TRUE(ok.error.empty()) << ok.error;
    EXPECT_EQ(ok.base_steps, 300u);
    EXPECT_EQ(ok.base_dt, 0.002);
    const DurationPlan bad = plan_duration(scene, 0.5);
    EXPECT_NE(bad.error.find("variant 'coarse'"), std::string::npos) << bad.error;
    EXPECT_FALSE(plan_duration(scene, -1.0).error.empty());
    EXPECT_FALSE(run_comparison(scene, lasting(0.5)).error.empty());
}

TEST(Metrics, LockstepLeavesEveryVariantAtTheCommonTime) {
    Scene scene = throw_scene({1, 1, 0}, Method::semi_implicit_euler, 0.002);
    IntegratorSettings coarse = scene.integrator;
    coarse.dt = 0.006;
    scene.variants = {{"fine", {}, {}, {}, {}, {}, {}}, {"coarse", {}, {}, {}, {}, coarse, {}}};
    const Comparison c = run_comparison(scene, lasting(0.6));
    ASSERT_TRUE(c.error.empty());
    EXPECT_EQ(c.variants[0].steps, 300u);
    EXPECT_EQ(c.variants[1].steps, 100u);
    EXPECT_NEAR(c.variants[0].simulated_seconds, 0.6, 1e-12);
    EXPECT_NEAR(c.variants[1].simulated_seconds, 0.6, 1e-12);
}

TEST(Metrics, CancelFlagStopsTheRun) {
    const Scene scene = throw_scene({1, 1, 0}, Method::semi_implicit_euler, 0.002);
    std::atomic<bool> cancel{true};
    CompareOptions o;
    o.duration_s = 2.0;
    o.cancel = &cancel;
    const Comparison c = run_comparison(scene, o);
    EXPECT_TRUE(c.cancelled);
    ASSERT_EQ(c.variants.size(), 1u);
    EXPECT_EQ(c.variants[0].steps, 0u);
}

}  // namespace
}  // namespace pl
