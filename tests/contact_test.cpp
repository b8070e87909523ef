// Wall contact: bounce times and time to rest against the closed form for a dropped ball,
// restitution 0 and 1, friction, corners, fast particles.
#include "physics/stepping/contact.hpp"
#include "physics/stepping/energy.hpp"
#include "physics/stepping/particle_stepper.hpp"
#include "physics/stepping/simulation.hpp"
#include "test_scenes.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace pl {
namespace {

using test::ball_at_height;
using test::drop_model;
using test::of_kind;

constexpr double g = 9.81;

// Closed form: t_n = t0 (1 + 2 (e + ... + e^n)), t0 = sqrt(2 h / g).
double bounce_time(double h, double e, int n) {
    double sum = 0, p = 1;
    for (int k = 1; k <= n; ++k) sum += (p *= e);
    return std::sqrt(2 * h / g) * (1 + 2 * sum);
}

std::vector<Event> run_drop(double e, Method m, double dt, double duration, double h = 2.0) {
    Simulation sim(drop_model(e, m, dt), {ball_at_height(h)});
    std::vector<Event> events;
    while (sim.time() < duration) {
        sim.step();
        for (const Event& ev : sim.drain_events()) events.push_back(ev);
    }
    return events;
}

TEST(Contact, BounceTimesMatchClosedFormWithSemiImplicitEuler) {
    const double e = 0.8, h = 2.0;
    const auto bounces = of_kind(run_drop(e, Method::semi_implicit_euler, 1e-4, 5.0), EventKind::bounce);
    ASSERT_GE(bounces.size(), 5u);
    for (int n = 0; n < 5; ++n) EXPECT_NEAR(bounces[n].t, bounce_time(h, e, n), 2e-3) << "bounce " << n;
}

TEST(Contact, BounceTimeErrorConvergesAtFirstOrderForSemiImplicitEuler) {
    const double e = 0.8, h = 2.0;
    std::vector<double> errors;
    for (double dt : {4e-3, 2e-3, 1e-3}) {
        const auto b = of_kind(run_drop(e, Method::semi_implicit_euler, dt, 2.5), EventKind::bounce);
        ASSERT_GE(b.size(), 3u);
        errors.push_back(std::abs(b[2].t - bounce_time(h, e, 2)));
    }
    for (std::size_t i = 1; i < errors.size(); ++i) {
        const double order = std::log2(errors[i - 1] / errors[i]);
        EXPECT_NEAR(order, 1.0, 0.2);
    }
}

TEST(Contact, HigherOrderMethodsLocateBouncesToRoundOff) {
    // Constant gravity is integrated exactly by Verlet, RK4 and Dormand-Prince, and the time of
    // impact is located on the step's own trajectory: only the root finder's error remains.
    const double e = 0.8, h = 2.0;
    for (Method m : {Method::velocity_verlet, Method::rk4, Method::dopri5}) {
        const auto b = of_kind(run_drop(e, m, 0.01, 2.5), EventKind::bounce);
        ASSERT_GE(b.size(), 3u) << to_string(m);
        for (int n = 0; n < 3; ++n) EXPECT_NEAR(b[n].t, bounce_time(h, e, n), 1e-9) << to_string(m) << " bounce " << n;
    }
}

TEST(Contact, ComesToRestAtTheClosedFormTime) {
    const double e = 0.8, h = 2.0, rest_speed = 1e-3, dt = 1e-4;
    Simulation sim(drop_model(e, Method::rk4, dt, rest_speed), {ball_at_height(h)});
    double t_rest = -1;
    while (sim.time() < 20 && t_rest < 0) {
        sim.step();
        for (const Event& ev : sim.drain_events())
            if (ev.kind == EventKind::rest) t_rest = ev.t;
    }
    ASSERT_GT(t_rest, 0);
    const double t0 = std::sqrt(2 * h / g);
    // Resting replaces the remaining micro-bounces, whose total time is below 2 v_rest / (g (1 - e)).
    const double cut = 2 * rest_speed / (g * (1 - e)) / e;
    EXPECT_NEAR(t_rest, t0 * (1 + e) / (1 - e), cut + dt);
    // At rest: exactly on the floor, velocity exactly zero, and it stays there.
    const double floor_contact = sim.model().room.floor_y() + sim.state().radius[0];
    sim.run_until(sim.time() + 5.0);
    EXPECT_EQ(sim.state().y[0], floor_contact);
    EXPECT_EQ(sim.state().velocity(0), Vec3(0.0));
    EXPECT_NE(sim.state().resting[0] & (1u << Wall::y_min), 0);
}

TEST(Contact, RestitutionZeroSticksAtOnce) {
    Simulation sim(drop_model(0.0, Method::semi_implicit_euler, 1e-3, 0.05), {ball_at_height(1.0)});
    sim.run_until(1.0);
    const auto events = sim.drain_events();
    ASSERT_FALSE(events.empty());
    EXPECT_EQ(events.front().kind, EventKind::rest);
    EXPECT_EQ(of_kind(events, EventKind::bounce).size(), 0u);
    EXPECT_EQ(sim.state().vy[0], 0.0);
}

TEST(Contact, RestitutionOneKeepsEnergyOverAHundredThousandBounces) {
    // 1e5 bounces of a small hop; Verlet is exact for constant gravity, so energy must be kept
    // to round-off and never grow.
    Model m = drop_model(1.0, Method::velocity_verlet, 0.01, 0.0);
    m.room.center = {0, 0.5, 0};
    m.room.size = {1, 1, 1};
    Simulation sim(m, {ball_at_height(0.2, 0.05)});
    const double e0 = total_energy(sim.state(), m.world.gravity, m.room).total_mechanical();
    std::size_t bounces = 0;
    double max_e = e0;
    while (bounces < 100000) {
        sim.step();
        for (const Event& ev : sim.drain_events()) bounces += ev.kind == EventKind::bounce;
        max_e = std::max(max_e, total_energy(sim.state(), m.world.gravity, m.room).total_mechanical());
    }
    const double e1 = total_energy(sim.state(), m.world.gravity, m.room).total_mechanical();
    EXPECT_NEAR(e1, e0, 1e-9 * e0);
    EXPECT_LE(max_e, e0 * (1 + 1e-9));
}

TEST(Contact, SlidingBallStopsAtClosedFormDistance) {
    // Kinetic friction mu m g decelerates a ball sliding on the floor: d = v^2 / (2 mu g).
    const double mu = 0.3, v0 = 2.0, dt = 1e-4;
    Model m = drop_model(0.5, Method::semi_implicit_euler, dt, 0.05);
    m.contact.friction = mu;
    m.room.size = {10, 10, 10};
    ParticleSpec p = ball_at_height(0.0);
    p.position.x = -4;
    p.velocity = {v0, 0, 0};
    Simulation sim(m, {p});
    sim.run_until(2.0);
    const double expected = v0 * v0 / (2 * mu * g);
    EXPECT_NEAR(sim.state().x[0] - p.position.x, expected, v0 * dt * 2);
    EXPECT_EQ(sim.state().velocity(0), Vec3(0.0));
    bool stopped = false;
    for (const Event& ev : sim.events()) stopped |= ev.kind == EventKind::stop;
    EXPECT_TRUE(stopped);
}

TEST(Contact, StaticFrictionHoldsOnASlope) {
    // Gravity tilted 10 degrees from the floor normal: tan(10 deg) = 0.176 < mu = 0.3 holds it.
    Model m = drop_model(0.5, Method::semi_implicit_euler, 1e-3, 0.05);
    m.contact.friction = 0.3;
    const double a = 10.0 * M_PI / 180;
    m.world.gravity = {g * std::sin(a), -g * std::cos(a), 0};
    Simulation sim(m, {ball_at_height(0.0)});
    sim.run_until(2.0);
    EXPECT_EQ(sim.state().velocity(0), Vec3(0.0));
    // Steeper than the friction angle it slides.
    m.world.gravity = {g * std::sin(0.5), -g * std::cos(0.5), 0};
    Simulation slide(m, {ball_at_height(0.0)});
    slide.run_until(0.5);
    EXPECT_GT(slide.state().vx[0], 0.5);
}

TEST(Contact, RestingInACornerForAnHourDoesNotMove) {
    Model m = drop_model(0.5, Method::semi_implicit_euler, 0.01, 0.05);
    m.contact.friction = 0.3;
    const Room& r = m.room;
    ParticleSpec p{{r.min_corner().x + 0.05, r.floor_y() + 0.05, r.min_corner().z + 0.05}, {0, 0, 0}, 0.1, 0.05};
    Simulation sim(m, {p});
    sim.run_until(3600.0);
    EXPECT_EQ(sim.state().position(0), p.position);
    EXPECT_EQ(sim.state().velocity(0), Vec3(0.0));
    for (const Event& ev : sim.events()) EXPECT_NE(ev.kind, EventKind::bounce);
}

TEST(Contact, FastParticleNeverTunnels) {
    // 1 km/s in a 1 m room with dt = 0.01: ten walls' worth of travel per step.
    Model m = drop_model(1.0, Method::semi_implicit_euler, 0.01, 0.0);
    m.room.center = {0, 0.5, 0};
    m.room.size = {1, 1, 1};
    ParticleSpec p{{0, 0.5, 0}, {600, 500, 611}, 0.1, 0.05};
    Simulation sim(m, {p});
    const RoomBounds room(m.room);
    for (int k = 0; k < 1000; ++k) {
        sim.step();
        for (int w = 0; w < wall_count; ++w) ASSERT_GE(room.distance(w, sim.state().position(0), 0.05), -1e-12);
    }
    EXPECT_GT(of_kind(sim.events(), EventKind::bounce).size(), 5000u);
    // Elastic walls and no drag: the speed is kept.
    EXPECT_NEAR(glm::length(sim.state().velocity(0)), glm::length(p.velocity), 1.0);
}

TEST(Contact, HugeRadiusStaysInside) {
    Model m = drop_model(0.9, Method::rk4, 0.005, 0.01);
    m.room.center = {0, 1, 0};
    m.room.size = {2, 2, 2};
    ParticleSpec p{{0, 1, 0}, {3, 2, -1}, 1.0, 0.98};  // 49% of the room
    Simulation sim(m, {p});
    const RoomBounds room(m.room);
    for (int k = 0; k < 4000; ++k) {
        sim.step();
        for (int w = 0; w < wall_count; ++w) ASSERT_GE(room.distance(w, sim.state().position(0), 0.98), -1e-12);
    }
}

TEST(Contact, ZeroGravityBouncesForeverWithoutResting) {
    Model m = drop_model(1.0, Method::semi_implicit_euler, 0.01, 0.05);
    m.world.gravity = Vec3(0.0);
    ParticleSpec p{{0, 5, 0}, {0.01, 0.02, 0.0}, 0.1, 0.05};  // slower than rest_speed
    Simulation sim(m, {p});
    sim.run_until(400.0);
    EXPECT_EQ(sim.state().resting[0], 0);
    EXPECT_NEAR(glm::length(sim.state().velocity(0)), glm::length(p.velocity), 1e-12);
}

TEST(Contact, GravityAlongXRestsOnTheXWall) {
    Model m = drop_model(0.6, Method::rk4, 1e-3, 0.05);
    m.world.gravity = {9.81, 0, 0};
    ParticleSpec p{{0, 5, 0}, {0, 0, 0}, 0.1, 0.05};
    Simulation sim(m, {p});
    sim.run_until(10.0);
    EXPECT_NE(sim.state().resting[0] & (1u << Wall::x_max), 0);
    EXPECT_EQ(sim.state().x[0], m.room.max_corner().x - 0.05);
    EXPECT_EQ(sim.state().velocity(0), Vec3(0.0));
}

TEST(Contact, KickLiftsARestingBall) {
    Simulation sim(drop_model(0.0, Method::semi_implicit_euler, 1e-3, 0.05), {ball_at_height(0.0)});
    sim.run_until(0.1);
    ASSERT_NE(sim.state().resting[0], 0);
    sim.set_velocity(0, {0, 3, 0});
    EXPECT_EQ(sim.state().resting[0], 0);
    sim.run_until(0.2);
    EXPECT_GT(sim.state().y[0], sim.model().room.floor_y() + 0.05 + 0.1);
}

TEST(Contact, EdgeAndCornerHitsReflectAllComponents) {
    // Aimed exactly at a corner: all three walls are hit in one step.
    Model m = drop_model(1.0, Method::rk4, 0.01, 0.0);
    m.world.gravity = Vec3(0.0);
    m.room.center = {0, 0, 0};
    m.room.size = {2, 2, 2};
    ParticleSpec p{{0, 0, 0}, {1, 1, 1}, 0.1, 0.1};
    Simulation sim(m, {p});
    sim.run_until(1.0);  // reaches the corner at t = 0.9
    EXPECT_NEAR(sim.state().vx[0], -1.0, 1e-12);
    EXPECT_NEAR(sim.state().vy[0], -1.0, 1e-12);
    EXPECT_NEAR(sim.state().vz[0], -1.0, 1e-12);
    EXPECT_EQ(of_kind(sim.events(), EventKind::bounce).size(), 3u);
}

}  // namespace
}  // namespace pl

namespace pl {
namespace {

// The closed-form time of impact the Euler and Verlet steps use: the root of the quadratic wall
// distance, the earliest one, from the stable formula even where the naive one cancels.
TEST(ContactRoot, FirstRootOfTheWallDistance) {
    // Falling from 1 m under g: d = 1 - g/2 s^2 (kappa 1/2), root sqrt(2/g).
    EXPECT_NEAR(first_contact_root(1.0, 0.0, -0.5 * g, 10.0), std::sqrt(2.0 / g), 1e-15);
    // Moving in at 2 m/s, no acceleration: 0.5 s.
    EXPECT_DOUBLE_EQ(first_contact_root(1.0, -2.0, 0.0, 10.0), 0.5);
    // Thrown up from the wall at 3 m/s: back on it at 2 * 3 / g; not at 0.
    EXPECT_NEAR(first_contact_root(0.0, 3.0, -0.5 * g, 10.0), 6.0 / g, 1e-15);
    // On the wall moving in: contact now.
    EXPECT_EQ(first_contact_root(0.0, -1.0, -5.0, 1.0), 0.0);
    // Two roots in the step (moving in fast, decelerated away from the wall): the first one.
    EXPECT_NEAR(first_contact_root(1.0, -4.0, 2.0, 10.0), 1.0 - std::sqrt(0.5), 1e-15);
    // Fast and close: b^2 >> 4 c d0, where -b + sqrt(b^2 - 4 c d0) would lose every digit.
    const double s = first_contact_root(1e-9, -300.0, -4.9, 1.0);
    EXPECT_NEAR(s, 1e-9 / 300.0, 1e-24);
    // Round-off says the wall is not reached inside the step: the end of the step.
    EXPECT_EQ(first_contact_root(1.0, -0.5, 0.0, 1.0), 1.0);
    EXPECT_EQ(first_contact_root(1.0, 0.0, 1.0, 1.0), 1.0);
}

// The located impact is where the step's own trajectory meets the wall: semi-implicit Euler's
// positions lie on the parabola of its true velocity u = v - g dt / 2 (particle_stepper.hpp), so
// with one big step from rest the bounce time is the root of drop + s u - g s^2 / 2 = 0, and the
// impact speed is |u - g s|.
TEST(ContactRoot, SemiImplicitEulerImpactIsOnItsParabola) {
    const double dt = 0.5;
    Model m = drop_model(0.5, Method::semi_implicit_euler, dt, 0.0);
    Simulation sim(m, {ball_at_height(1.0)});
    sim.step();
    const auto bounces = of_kind(sim.events(), EventKind::bounce);
    ASSERT_EQ(bounces.size(), 1u);
    const double drop = 1.0;  // height of the sphere's bottom above the floor
    const double s = 0.5 * (-dt + std::sqrt(dt * dt + 8 * drop / g));
    EXPECT_NEAR(bounces[0].t, s, 1e-12);
    EXPECT_NEAR(bounces[0].speed_in, g * (dt / 2 + s), 1e-9);
}

// Adaptive Dormand-Prince integrates constant gravity exactly, so its internal steps grow to the
// whole 1 s step; the one that spans the apex starts and ends below the ceiling. A ball whose apex
// is 1 cm beyond the ceiling's contact plane must still hit it (found on the dense output), at
// the closed-form time, and one whose apex stays 1 cm below must not.
TEST(Contact, AdaptiveDormandPrinceFindsAWallPassedWithinOneInternalStep) {
    const double r = 0.05, y0 = 9.0, e = 0.8;
    for (const double beyond : {0.01, -0.01}) {
        Model m = drop_model(e, Method::dopri5, 1.0);
        m.integrator.rtol = 1e-3;
        m.integrator.atol = 1e-6;
        const double plane = m.room.max_corner().y - r;
        const double v0 = std::sqrt(2 * g * (plane + beyond - y0));
        Simulation sim(m, {{{0, y0, 0}, {0, v0, 0}, 0.1, r}});
        sim.step();
        const auto bounces = of_kind(sim.drain_events(), EventKind::bounce);
        if (beyond < 0) {
            EXPECT_TRUE(bounces.empty());
            EXPECT_NEAR(sim.state().y[0], y0 + v0 - 0.5 * g, 1e-9);  // free flight, no wall touched
            continue;
        }
        ASSERT_EQ(bounces.size(), 1u);
        EXPECT_EQ(bounces[0].wall, Wall::y_max);
        const double t_hit = (v0 - std::sqrt(v0 * v0 - 2 * g * (plane - y0))) / g;
        EXPECT_NEAR(bounces[0].t, t_hit, 1e-9);
        // After the hit it falls from the plane with e times the speed it arrived with.
        const double v_hit = v0 - g * t_hit, rest = 1.0 - t_hit;
        EXPECT_NEAR(sim.state().y[0], plane - e * v_hit * rest - 0.5 * g * rest * rest, 1e-9);
        EXPECT_LE(sim.state().y[0], plane);
    }
}

}  // namespace
}  // namespace pl
