// The contact fidelity gaps of the physics issue: explicit Euler's rest trap, energy at
// semi-implicit Euler's bounces, resting contact as a state whatever rest_speed is, the impact
// cap and runaway states, symmetric corners, and the stability guard of adaptive Dormand-Prince.
#include "physics/model/drag.hpp"
#include "physics/stepping/energy.hpp"
#include "physics/stepping/simulation.hpp"
#include "physics/studies/stability_study.hpp"
#include "test_scenes.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace pl {
namespace {

using test::ball_at_height;
using test::drop_model;
using test::of_kind;

constexpr double g = 9.81;

bool has_warning(const Simulation& sim, WarningKind kind) {
    for (const Warning& w : sim.warnings())
        if (w.kind == kind) return true;
    return false;
}

// Closed form of a drop from `height` with restitution e and rest threshold v_rest: the ball
// rests at the first impact whose rebound e v_k is below v_rest. Returns {bounces, rest time}.
std::pair<int, double> drop_rest(double height, double e, double v_rest) {
    const double t0 = std::sqrt(2 * height / g);
    double v = g * t0, t = t0;
    int bounces = 0;
    while (e * v >= v_rest) {
        v *= e;
        t += 2 * v / g;
        ++bounces;
    }
    return {bounces, t};
}

// Bounces and rest time of a simulated drop (rest time -1 if it never rested in `duration`).
std::pair<int, double> simulate_rest(Simulation& sim, double duration) {
    int bounces = 0;
    double rest = -1;
    while (sim.time() < duration && rest < 0) {
        sim.step_n(16);
        for (const Event& e : sim.drain_events()) {
            bounces += e.kind == EventKind::bounce;
            if (e.kind == EventKind::rest) rest = e.t;
        }
    }
    return {bounces, rest};
}

TEST(ContactFidelity, ExplicitEulerAboveTheRestTrapWarnsAndNeverRests) {
    // dt > rest_speed (1 - e) / (e g) = 1.27 ms: the rebounds tend to e g dt / (1 - e) > rest_speed.
    const double e = 0.8, rest_speed = 0.05;
    Simulation trapped(drop_model(e, Method::explicit_euler, 2e-3, rest_speed), {ball_at_height(1.0)});
    EXPECT_EQ(simulate_rest(trapped, 30.0).second, -1.0);
    ASSERT_TRUE(has_warning(trapped, WarningKind::no_rest));
    EXPECT_NEAR(no_rest_dt(trapped.model()), rest_speed * (1 - e) / (e * g), 1e-15);
    Simulation fine(drop_model(e, Method::explicit_euler, 1e-3, rest_speed), {ball_at_height(1.0)});
    EXPECT_GT(simulate_rest(fine, 30.0).second, 0.0);
    EXPECT_FALSE(has_warning(fine, WarningKind::no_rest));
}

TEST(ContactFidelity, ExplicitEulerBallThatShouldSlideKeepsHoppingAndIsWarned) {
    // Launched low and fast along the floor with friction: every other method lands it sliding.
    Model m = drop_model(0.8, Method::explicit_euler, 4e-3, 0.05);  // trapped above 1.27 ms
    m.contact.friction = 0.05;
    Simulation sim(m, {{{-1.5, 0.06, 0}, {3.0, 0.5, 0}, 0.1, 0.05}});
    sim.run_until(10.0);
    EXPECT_FALSE(of_kind(sim.drain_events(), EventKind::bounce).empty());
    EXPECT_TRUE(has_warning(sim, WarningKind::no_rest));
}

TEST(ContactFidelity, StabilityStudySeesTheExplicitEulerRestTrap) {
    StabilityBase base = default_stability_base();
    base.contact.rest_speed = 0.05;
    StabilityCase c;
    c.method = Method::explicit_euler;
    c.dt = 5e-3;  // limit 0.05 * 0.2 / (0.8 * 9.81) = 1.3 ms
    c.speed = 5.0;
    c.restitution = 0.8;
    const StabilityCell cell = classify_stability(base, c);
    EXPECT_TRUE(cell.jitter_checked);
    EXPECT_EQ(cell.outcome, StabilityOutcome::jitter) << cell.detail;
    c.method = Method::semi_implicit_euler;
    EXPECT_EQ(classify_stability(base, c).outcome, StabilityOutcome::stable);
}

TEST(ContactFidelity, SemiImplicitEulerElasticBounceKeepsEnergy) {
    Model m = drop_model(1.0, Method::semi_implicit_euler, 1e-3, 0.05);
    Simulation sim(m, {ball_at_height(1.0)});
    const double e0 = total_energy(sim.state(), m.world.gravity, m.room).total_mechanical();
    const auto [bounces, rest] = simulate_rest(sim, 60.0);
    EXPECT_EQ(rest, -1.0);
    EXPECT_GE(bounces, 60);
    // At step ends semi-implicit Euler's velocity is its mid-step one: off by g dt / 2 in speed.
    const double e1 = total_energy(sim.state(), m.world.gravity, m.room).total_mechanical();
    EXPECT_NEAR(e1, e0, 0.1 * 0.05 * e0);
    EXPECT_NEAR(e1, e0, sim.state().mass[0] * g * 1e-3 * std::sqrt(2 * g * 1.0));
}

TEST(ContactFidelity, RestitutionPresetRestsAtTheClosedForm) {
    // presets/restitution.json's e = 0.95 variant: 2 m drop, rest_speed 0.05, dt 1 ms.
    const double e = 0.95, height = 2.0, rest_speed = 0.05, dt = 1e-3;
    Model m = drop_model(e, Method::semi_implicit_euler, dt, rest_speed);
    Simulation sim(m, {ball_at_height(height, 0.033)});
    const auto [bounces, rest] = simulate_rest(sim, 60.0);
    const auto [want_bounces, want_rest] = drop_rest(height, e, rest_speed);
    EXPECT_NEAR(bounces, want_bounces, 1);
    EXPECT_NEAR(rest, want_rest, 0.01 * want_rest);
}

TEST(ContactFidelity, ElasticBouncesKeepEnergyForEveryMethodButExplicitEuler) {
    for (Method method : {Method::semi_implicit_euler, Method::velocity_verlet, Method::rk4, Method::dopri5,
                          Method::exponential}) {
        ASSERT_TRUE(keeps_bounce_energy(method));
        Simulation sim(drop_model(1.0, method, 2e-3, 0.0), {ball_at_height(0.5)});
        const auto [bounces, rest] = simulate_rest(sim, 20.0);
        EXPECT_EQ(rest, -1.0) << to_string(method);
        EXPECT_GE(bounces, 30) << to_string(method);
    }
    EXPECT_FALSE(keeps_bounce_energy(Method::explicit_euler));
}

// exact_under_constant_force (which the contact solver's push and its ledger follow) against what
// one step of each method does under gravity alone, far from the walls: x1 = x0 + v0 h + g h^2 / 2
// to round-off on the exact methods; the Euler methods off by g h^2 / 2 either way, which is the
// push share's 1 (x0 + v1 h) or 0 (x0 + v0 h).
TEST(ContactFidelity, TheMethodsExactUnderAConstantForceAreThoseWhoseStepIsExactUnderGravity) {
    const double h = 0.01, g = 9.81;
    for (Method method : {Method::explicit_euler, Method::semi_implicit_euler, Method::velocity_verlet, Method::rk4,
                          Method::dopri5, Method::exponential}) {
        Model m = drop_model(1.0, method, h, 0.0);
        Simulation sim(m, {ParticleSpec{Vec3(0.0, 5.0, 0.0), Vec3(1.0, 2.0, 0.0), 0.1, 0.05}});
        sim.step();
        const double y = 5.0 + 2.0 * h - 0.5 * g * h * h;
        const double off = (sim.state().y[0] - y) / (0.5 * g * h * h);  // in units of g h^2 / 2
        if (exact_under_constant_force(method)) {
            EXPECT_NEAR(off, 0.0, 1e-9) << to_string(method);
            EXPECT_EQ(constant_push_share(method), 0.5) << to_string(method);
        } else {
            EXPECT_NEAR(std::abs(off), 1.0, 1e-9) << to_string(method);
            EXPECT_EQ(constant_push_share(method), off < 0.0 ? 1.0 : 0.0) << to_string(method);
        }
    }
}

// Balls lying on the floor (not yet marked resting), sliding without friction, e = 1 and
// rest_speed 0: one contact each to find they rest, then sliding, not bouncing in place.
TEST(ContactFidelity, LyingOnTheFloorWithRestSpeedZeroIsRestingContact) {
    for (KernelChoice kernel : {KernelChoice::fast, KernelChoice::generic}) {
        for (Method method : {Method::semi_implicit_euler, Method::velocity_verlet, Method::rk4}) {
            Model m = drop_model(1.0, method, 2e-3, 0.0);
            m.room.size = {400, 10, 400};
            std::vector<ParticleSpec> balls;
            for (int i = 0; i < 100; ++i)
                balls.push_back({{-100.0 + 2 * i, 0.05, 0}, {1.0, 0, 0.01 * i}, 0.1, 0.05});
            Simulation sim(m, balls);
            sim.set_kernel(kernel);
            const std::uint64_t steps = 20;
            sim.step_n(steps);
            const ForceCounters& c = sim.counters();
            EXPECT_LE(c.contacts, balls.size()) << to_string(method);
            EXPECT_LE(c.gravity, 10 * steps * balls.size()) << to_string(method);
            for (std::size_t i = 0; i < balls.size(); ++i) {
                EXPECT_EQ(sim.state().resting[i], 1u << Wall::y_min);
                EXPECT_EQ(sim.state().vx[i], 1.0);
            }
        }
    }
}

TEST(ContactFidelity, MoreImpactsThanTheCapFreezeAndReport) {
    for (KernelChoice kernel : {KernelChoice::fast, KernelChoice::generic}) {
        Model m = drop_model(1.0, Method::semi_implicit_euler, 0.01, 0.0);
        m.world.gravity = Vec3(0.0);
        m.room.size = {0.11, 0.11, 0.11};  // 1 cm of free travel per axis for r = 5 cm
        Simulation sim(m, {{{0, 5, 0}, {100.0, 0, 0}, 0.1, 0.05}});  // 1 m per step: 100 impacts
        sim.set_kernel(kernel);
        sim.step();
        EXPECT_EQ(sim.state().frozen[0], 1);
        ASSERT_TRUE(has_warning(sim, WarningKind::impact_cap));
        EXPECT_EQ(of_kind(sim.events(), EventKind::frozen).size(), 1u);
    }
}

TEST(ContactFidelity, RunawayFiniteStateIsFrozenLikeNaN) {
    for (KernelChoice kernel : {KernelChoice::fast, KernelChoice::generic}) {
        Model m = drop_model(1.0, Method::semi_implicit_euler, 1e-9, 0.0);
        m.room.size = {1e5, 1e5, 1e5};
        m.room.center = {0, 0, 0};
        Simulation sim(m, {{{0, 0, 0}, {1e12, 0, 0}, 0.1, 0.05}});  // 1 km per step, far faster than light
        sim.set_kernel(kernel);
        sim.step();
        EXPECT_EQ(sim.state().frozen[0], 1);
        ASSERT_TRUE(has_warning(sim, WarningKind::runaway));
        EXPECT_EQ(sim.state().x[0], 0.0);  // the last credible state is kept
    }
}

TEST(ContactFidelity, SymmetricCornerHitWithFrictionStaysSymmetric) {
    for (KernelChoice kernel : {KernelChoice::fast, KernelChoice::generic}) {
        Model m = drop_model(0.8, Method::semi_implicit_euler, 1e-3, 0.0);
        m.world.gravity = Vec3(0.0);
        m.contact.friction = 0.3;
        m.room.center = {0, 0, 0};
        m.room.size = {2, 2, 2};
        // 0.4 m from the x_max and the y_min contact planes, moving into both equally.
        Simulation sim(m, {{{0.5, -0.5, 0}, {1.0, -1.0, 0.5}, 0.1, 0.1}});
        sim.set_kernel(kernel);
        sim.run_until(0.6);
        const Vec3 v = sim.state().velocity(0);
        ASSERT_LT(v.x, 0.0);
        EXPECT_EQ(v.x, -v.y);
        EXPECT_NEAR(-v.x, 0.8, 1e-12);
        EXPECT_EQ(of_kind(sim.events(), EventKind::bounce).size(), 2u);
    }
}

TEST(ContactFidelity, AdaptiveDormandPrinceIsNotWarnedOnAStiffScene) {
    Model m = drop_model(0.5, Method::dopri5, 0.05, 0.05);
    m.drag.model = DragModel::linear;
    m.drag.linear_b = 100.0 * 0.1;  // k = 100 1/s, dt k = 5 > 3.3
    Simulation adaptive(m, {ball_at_height(3.0)});
    adaptive.run_until(1.0);
    EXPECT_FALSE(has_warning(adaptive, WarningKind::stability));
    // Terminal speed g / k, which it solves correctly.
    EXPECT_NEAR(adaptive.state().vy[0], -g / 100.0, 1e-3);
    m.integrator.adaptive = false;
    Simulation fixed(m, {ball_at_height(3.0)});
    fixed.run_until(0.2);
    EXPECT_TRUE(has_warning(fixed, WarningKind::stability));
}

}  // namespace
}  // namespace pl

namespace pl {
namespace {

// A heavy ball falls from rest: first below the quadratic model's validity range (Re < 1e3: a
// harmless note, drag is negligible there), then above it (Re > 2e5 from 45 m/s): the second,
// real warning must not be masked by the first.
TEST(ContactFidelity, DragValidityAboveTheRangeIsRaisedAfterANoteBelowIt) {
    Model m = test::drop_model(0.5, Method::semi_implicit_euler, 2e-3, 0.05);
    m.room.center = {0, 500, 0};
    m.room.size = {10, 1000, 10};
    m.drag.model = DragModel::quadratic;
    m.drag.cd = 0.47;
    Simulation sim(m, {{{0, 990, 0}, {0, 0, 0}, 1.0, 0.033}});
    sim.run_until(8.0);
    const ReRange valid = drag_validity(DragModel::quadratic);
    bool below = false, above = false;
    for (const Warning& w : sim.warnings()) {
        if (w.kind != WarningKind::drag_validity) continue;
        below |= w.value < valid.lo;
        above |= w.value > valid.hi;
    }
    EXPECT_TRUE(below);
    EXPECT_TRUE(above);
}

}  // namespace
}  // namespace pl

namespace pl {
namespace {

// A ball sliding on the floor stops after v^2 / (2 mu g) at v / (mu g): exactly (to round-off)
// even at a coarse step, for every method, now that the stop is located inside its step (it was
// off by about v dt / 2: 2 cm here).
TEST(ContactFidelity, SlidingStopIsLocatedInsideTheStep) {
    const double mu = 0.3, v0 = 2.0, dt = 0.02;
    for (KernelChoice kernel : {KernelChoice::fast, KernelChoice::generic}) {
        for (Method method : {Method::semi_implicit_euler, Method::velocity_verlet, Method::rk4}) {
            Model m = drop_model(0.5, method, dt, 0.05);
            m.contact.friction = mu;
            Simulation sim(m, {{{-1.5, 0.05, 0}, {v0, 0, 0}, 0.1, 0.05}});
            sim.set_kernel(kernel);
            sim.run_until(1.0);
            const auto stops = of_kind(sim.events(), EventKind::stop);
            ASSERT_EQ(stops.size(), 1u) << to_string(method);
            EXPECT_NEAR(sim.state().x[0] + 1.5, v0 * v0 / (2 * mu * g), 1e-9) << to_string(method);
            EXPECT_NEAR(stops[0].t, v0 / (mu * g), 1e-9) << to_string(method);
        }
    }
}

}  // namespace
}  // namespace pl
