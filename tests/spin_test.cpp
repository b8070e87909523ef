// Spin: rolling contact (stepping/spin_contact.hpp) against its closed forms, the impact with
// spin against the rigid-body impact formula, and Magnus lift (terms/magnus.hpp) against an
// independent high-order reference; convergence orders and the energy ledger's spin lines.
#include "physics/model/terms/magnus.hpp"
#include "physics/stepping/energy.hpp"
#include "physics/stepping/simulation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace pl {
namespace {

constexpr double g = 9.81;

// A level floor, a large room, friction coupled to spin.
Model floor_model(double mu, double c_rr, Method method = Method::semi_implicit_euler, double dt = 1e-3) {
    Model m;
    m.room.center = {0, 5, 0};
    m.room.size = {100, 10, 100};
    m.contact.restitution = 0.5;
    m.contact.friction = mu;
    m.contact.spin = true;
    m.contact.rolling_resistance = c_rr;
    m.integrator.method = method;
    m.integrator.dt = dt;
    return m;
}

constexpr double radius = 0.033, mass = 0.057, v0 = 3.0;

ParticleSpec sliding_ball(Inertia shape) {
    ParticleSpec p{{-40, radius, 0}, {v0, 0, 0}, mass, radius};
    p.inertia = shape;
    return p;
}

// Sliding without spin, then rolling at v0 / (1 + k): 5/7 solid, 3/5 hollow; the slide lasts
// t_s = v0 k / ((1 + k) mu g) and covers v0 t_s - mu g t_s^2 / 2 (12 v0^2 / (49 mu g) solid).
TEST(Spin, SlidingBallRollsAtFiveSeventhsOrThreeFifthsInClosedForm) {
    const double mu = 0.2;
    for (const Inertia shape : {Inertia::solid, Inertia::hollow}) {
        const double k = inertia_factor(shape);
        const double t_s = v0 * k / ((1.0 + k) * mu * g);
        const double d_s = v0 * t_s - 0.5 * mu * g * t_s * t_s;
        const double v_roll = v0 / (1.0 + k);
        EXPECT_NEAR(v_roll / v0, shape == Inertia::solid ? 5.0 / 7.0 : 3.0 / 5.0, 1e-15);
        if (shape == Inertia::solid) {
            EXPECT_NEAR(d_s, 12.0 * v0 * v0 / (49.0 * mu * g), 1e-12);
        }
        Simulation sim(floor_model(mu, 0.0), {sliding_ball(shape)});
        sim.run_until(0.1);  // sliding
        const double t = sim.time();
        EXPECT_NEAR(sim.state().vx[0], v0 - mu * g * t, 1e-12);
        EXPECT_NEAR(sim.state().x[0] + 40.0, v0 * t - 0.5 * mu * g * t * t, 1e-11);
        EXPECT_NEAR(sim.state().wz[0], -mu * g * t / (k * radius), 1e-9);  // spun up by the friction torque
        sim.run_until(1.0);  // rolling, no resistance
        EXPECT_NEAR(sim.state().vx[0], v_roll, 1e-12);
        EXPECT_NEAR(sim.state().wz[0], -v_roll / radius, 1e-9);
        EXPECT_NEAR(sim.state().x[0] + 40.0, d_s + v_roll * (sim.time() - t_s), 1e-10);
        EXPECT_EQ(sim.state().y[0], radius);
    }
}

// From the rolling speed v_r, rolling resistance stops the ball after v_r^2 / (2 c_rr g), at
// t_s + v_r / (c_rr g); the energy at the start of the roll, (1 + k) m v_r^2 / 2, all goes to the
// rolling line, the slide's loss to the friction line, and the residual stays at round-off.
TEST(Spin, RollingResistanceStopsTheBallAtTheClosedFormDistance) {
    const double mu = 0.3, c_rr = 0.05, k = 0.4;
    const double t_s = v0 * k / ((1.0 + k) * mu * g);
    const double d_s = v0 * t_s - 0.5 * mu * g * t_s * t_s;
    const double v_r = v0 / (1.0 + k);
    Simulation sim(floor_model(mu, c_rr), {sliding_ball(Inertia::solid)});
    sim.run_until(t_s + v_r / (c_rr * g) + 0.5);
    EXPECT_EQ(sim.state().vx[0], 0.0);
    EXPECT_NEAR(sim.state().wz[0], 0.0, 1e-12);
    EXPECT_NEAR(sim.state().x[0] + 40.0, d_s + v_r * v_r / (2.0 * c_rr * g), 1e-10);
    const std::vector<Event> events = sim.drain_events();
    const auto stop = std::find_if(events.begin(), events.end(), [](const Event& e) { return e.kind == EventKind::stop; });
    ASSERT_NE(stop, events.end());
    EXPECT_NEAR(stop->t, t_s + v_r / (c_rr * g), 1e-12);
    const EnergyBreakdown e = total_energy(sim.state(), sim.model().world.gravity, sim.model().room);
    EXPECT_NEAR(e.dissipated_rolling, 0.5 * (1.0 + k) * mass * v_r * v_r, 1e-12);
    EXPECT_NEAR(e.dissipated_friction, 0.5 * mass * v0 * v0 - 0.5 * (1.0 + k) * mass * v_r * v_r, 1e-12);
    EXPECT_LT(std::abs(e.residual()), 1e-13);
}

// The rigid-body impact (Stronge; Cross 2002) for a ball with spin w_z hitting the floor at
// (vx, vy < 0): slip s = vx + R w_z; grip where mu (1 + e) |vy| >= k |s| / (1 + k), then
// vx' = vx - k s / (1 + k), else vx' = vx - mu (1 + e) |vy| sign(s); vy' = e |vy|.
double expected_vx_out(double vx, double vy, double wz, double mu, double e, double k) {
    const double s = vx + radius * wz;
    const double limit = mu * (1.0 + e) * std::abs(vy);
    return limit >= k * std::abs(s) / (1.0 + k) ? vx - k * s / (1.0 + k) : vx - std::copysign(limit, s);
}

struct Rebound {
    double vx, vy, wz;  // just after the bounce
};

Rebound bounce(double wz, double mu) {
    Model m = floor_model(mu, 0.0, Method::velocity_verlet, 1e-3);  // exact under constant gravity
    m.contact.restitution = 0.8;
    ParticleSpec p{{0, 1.0, 0}, {5, -3, 0}, mass, radius};
    p.spin = {0, 0, wz};
    Simulation sim(m, {p});
    sim.run_until(0.3);  // lands at 0.233 s
    const std::vector<Event> events = sim.drain_events();
    EXPECT_EQ(events.size(), 1u);
    const double t_hit = events.at(0).t;
    return {sim.state().vx[0], sim.state().vy[0] + g * (sim.time() - t_hit), sim.state().wz[0]};
}

TEST(Spin, TopspinAndBackspinReboundMatchTheRigidBodyImpact) {
    const double vy_in = -std::sqrt(3.0 * 3.0 + 2.0 * g * (1.0 - radius));
    // Topspin turns the ball's bottom backwards (w_z < 0 for a ball moving to +x).
    for (const double mu : {0.4, 0.1}) {
        for (const double wz : {-300.0, -100.0, 100.0}) {
            const Rebound r = bounce(wz, mu);
            EXPECT_NEAR(r.vx, expected_vx_out(5.0, vy_in, wz, mu, 0.8, 0.4), 1e-10) << mu << " " << wz;
            EXPECT_NEAR(r.vy, 0.8 * -vy_in, 1e-10);
        }
    }
    // The lesson: topspin leaves lower and faster than backspin.
    const Rebound top = bounce(-100.0, 0.4), back = bounce(100.0, 0.4);
    EXPECT_LT(std::atan2(top.vy, top.vx), std::atan2(back.vy, back.vx));
    EXPECT_NEAR(top.wz, -top.vx / radius, 1e-9);  // grip: it leaves rolling
    // Heavy topspin on a slippery floor kicks the ball forward.
    EXPECT_GT(bounce(-300.0, 0.1).vx, 5.0);
}

// ---------------------------------------------------------------- Magnus lift

// A spinning ball in open air with quadratic drag and Magnus lift.
Model air_model(Method method, double dt, LiftModel lift = LiftModel::sawicki) {
    Model m;
    m.room.size = Vec3(1e6);
    m.drag.model = DragModel::quadratic;
    m.drag.cd = 0.35;
    m.drag.lift = lift;
    m.drag.spin_decay_s = 2.0;  // short, so that the decay shows within the flight
    m.integrator.method = method;
    m.integrator.dt = dt;
    m.integrator.adaptive = false;
    return m;
}

const ParticleSpec pitch = [] {
    ParticleSpec p{{0, 0, 0}, {30, 2, 0}, 0.145, 0.0366};
    p.spin = {0, 150, 60};  // side spin (curve) and some backspin
    return p;
}();
constexpr double flight = 0.6;

// The same equations written out here, integrated by classic RK4 at a tiny step: independent of
// the engine's term code and integrators.
std::array<Vec3, 2> reference_flight(LiftModel lift) {
    const double rho = 1.225, area = std::numbers::pi * pitch.radius * pitch.radius;
    const double kd = 0.5 * rho * 0.35 * area / pitch.mass, kl = 0.5 * rho * area / pitch.mass;
    auto accel = [&](const Vec3& v, double t) {
        const Vec3 w = std::exp(-t / 2.0) * pitch.spin;
        const double s = pitch.radius * glm::length(w) / glm::length(v);
        const double c_l = lift == LiftModel::sawicki ? (s <= 0.1 ? 1.5 * s : 0.09 + 0.6 * s)
                                                      : 1.120 * s / (0.583 + 2.333 * s);
        return Vec3(0, -g, 0) - kd * glm::length(v) * v +
               kl * c_l * glm::length(v) * glm::cross(glm::normalize(w), v);
    };
    Vec3 x = pitch.position, v = pitch.velocity;
    const int n = 60000;
    const double h = flight / n;
    for (int i = 0; i < n; ++i) {
        const double t = i * h;
        const Vec3 a1 = accel(v, t), v2 = v + 0.5 * h * a1;
        const Vec3 a2 = accel(v2, t + 0.5 * h), v3 = v + 0.5 * h * a2;
        const Vec3 a3 = accel(v3, t + 0.5 * h), v4 = v + h * a3;
        const Vec3 a4 = accel(v4, t + h);
        x += h / 6.0 * (v + 2.0 * v2 + 2.0 * v3 + v4);
        v += h / 6.0 * (a1 + 2.0 * a2 + 2.0 * a3 + a4);
    }
    return {x, v};
}

TEST(Magnus, TrajectoryMatchesAnIndependentHighOrderReference) {
    for (const LiftModel lift : {LiftModel::sawicki, LiftModel::nathan}) {
        const std::array<Vec3, 2> ref = reference_flight(lift);
        Model m = air_model(Method::dopri5, 0.01, lift);
        m.integrator.adaptive = true;
        m.integrator.rtol = 1e-12;
        m.integrator.atol = 1e-12;
        Simulation sim(m, {pitch});
        sim.run_until(flight);
        EXPECT_LT(glm::length(sim.state().position(0) - ref[0]), 1e-9) << to_string(lift);
        EXPECT_LT(glm::length(sim.state().velocity(0) - ref[1]), 1e-9);
        EXPECT_NEAR(sim.state().wy[0], std::exp(-flight / 2.0) * 150.0, 1e-9);
        // The lift moved the ball sideways (the curve) by centimetres, against -z for w_y > 0, v_x > 0.
        EXPECT_LT(ref[0].z, -0.1);
    }
}

TEST(Magnus, ConvergesAtEachMethodsOrder) {
    const std::array<Vec3, 2> ref = reference_flight(LiftModel::sawicki);
    struct Case {
        Method method;
        double dt, order;
    };
    for (const Case c : {Case{Method::explicit_euler, 4e-3, 1}, Case{Method::semi_implicit_euler, 4e-3, 1},
                         Case{Method::velocity_verlet, 4e-3, 2}, Case{Method::rk4, 0.04, 4},
                         Case{Method::exponential, 4e-3, 1}}) {
        double err[2];
        for (int i = 0; i < 2; ++i) {
            Simulation sim(air_model(c.method, c.dt / (i + 1)), {pitch});
            sim.run_until(flight);
            err[i] = glm::length(sim.state().velocity(0) - ref[1]);
        }
        EXPECT_NEAR(std::log2(err[0] / err[1]), c.order, 0.2) << to_string(c.method);
    }
}

TEST(Magnus, LedgerResidualShrinksAtTheMethodsOrder) {
    // In a wind the lift does work (dot(a, v) != 0); the ledger carries it in the air-work line.
    for (const auto& [method, order] : {std::pair{Method::semi_implicit_euler, 1.0}, std::pair{Method::rk4, 4.0}}) {
        double residual[2];
        for (int i = 0; i < 2; ++i) {
            Model m = air_model(method, (method == Method::rk4 ? 0.04 : 4e-3) / (i + 1));
            m.world.wind.kind = WindKind::constant;
            m.world.wind.velocity = {0, 0, 5};
            m.room.size = Vec3(100.0);  // a small potential energy: the residual stays above its round-off
            Simulation sim(m, {pitch});
            sim.run_until(flight);
            const EnergyBreakdown e = total_energy(sim.state(), m.world.gravity, m.room);
            residual[i] = std::abs(e.residual());
            EXPECT_GT(std::abs(e.wind_work), 20 * residual[i]);
        }
        EXPECT_NEAR(std::log2(residual[0] / residual[1]), order, 0.3) << to_string(method);
    }
}

TEST(Magnus, NotEvaluatedWhenOffAndRoutedToTheGenericKernel) {
    Simulation off(air_model(Method::rk4, 1e-3, LiftModel::none), {pitch});
    off.step_n(10);
    EXPECT_EQ(off.counters().magnus, 0u);
    EXPECT_GT(off.counters().fast_path, 0u);
    EXPECT_EQ(off.state().spin(0), pitch.spin);  // no lift, no contact coupling: the spin is left alone
    Simulation on(air_model(Method::rk4, 1e-3), {pitch});
    on.step_n(10);
    EXPECT_EQ(on.counters().magnus, on.counters().gravity);
    EXPECT_EQ(on.counters().fast_path, 0u);
}

}  // namespace
}  // namespace pl
