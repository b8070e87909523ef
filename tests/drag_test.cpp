// Drag and wind against closed forms: terminal velocities, the linear-drag trajectory, the
// vertical quadratic-drag tanh/tan solutions, the Cd(Re) correlation, and wind as a moving frame.
#include "physics/model/drag.hpp"
#include "physics/stepping/simulation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace pl {
namespace {

constexpr double g = 9.81;

Model open_air(DragSettings drag, Method method, double dt) {
    Model m;
    m.room.center = {0, 0, 0};
    m.room.size = Vec3(1e7);
    m.drag = drag;
    m.integrator.method = method;
    m.integrator.dt = dt;
    return m;
}

DragSettings linear(double b) { return {DragModel::linear, 0.47, b}; }
DragSettings quadratic(double cd) { return {DragModel::quadratic, cd, std::nullopt}; }

TEST(Drag, LinearTerminalVelocityIsMgOverB) {
    const double m = 0.1, b = 0.05;
    Simulation sim(open_air(linear(b), Method::rk4, 0.01), {{{0, 0, 0}, {0, 0, 0}, m, 0.05}});
    sim.run_until(60.0);  // 30 time constants
    EXPECT_NEAR(sim.state().vy[0], -m * g / b, 1e-9);
}

TEST(Drag, QuadraticTerminalVelocity) {
    const double m = 0.057, r = 0.033, cd = 0.47, rho = 1.225;
    Simulation sim(open_air(quadratic(cd), Method::rk4, 0.01), {{{0, 0, 0}, {0, 0, 0}, m, r}});
    sim.run_until(60.0);
    const double area = std::numbers::pi * r * r;
    EXPECT_NEAR(-sim.state().vy[0], std::sqrt(2 * m * g / (rho * cd * area)), 1e-8);
}

TEST(Drag, LinearDragTrajectoryMatchesClosedForm) {
    // v(t) = v_inf + (v0 - v_inf) e^{-kt}, x(t) = x0 + v_inf t + (v0 - v_inf)(1 - e^{-kt}) / k.
    const double m = 0.2, b = 0.3, k = b / m;
    const Vec3 v0{5, 8, -2}, gv{0, -g, 0}, v_inf = gv / k;
    const double t = 2.0;
    const Vec3 x_exact = v_inf * t + (v0 - v_inf) * (1 - std::exp(-k * t)) / k;
    const Vec3 v_exact = v_inf + (v0 - v_inf) * std::exp(-k * t);
    for (Method method : {Method::rk4, Method::dopri5, Method::exponential}) {
        Simulation sim(open_air(linear(b), method, 0.01), {{{0, 0, 0}, v0, m, 0.05}});
        sim.run_until(t);
        const double tol = method == Method::exponential ? 1e-12 : 1e-8;
        EXPECT_LT(glm::length(sim.state().position(0) - x_exact), tol) << to_string(method);
        EXPECT_LT(glm::length(sim.state().velocity(0) - v_exact), tol) << to_string(method);
    }
}

TEST(Drag, ExponentialStepStaysStableForStiffDrag) {
    // h k = 1000: the drag-exact step lands on terminal velocity at once.
    const double m = 0.01, b = 10.0;
    Simulation sim(open_air(linear(b), Method::exponential, 1.0), {{{0, 0, 0}, {50, 50, 0}, m, 0.05}});
    sim.step_n(5);
    EXPECT_NEAR(sim.state().vy[0], -m * g / b, 1e-12);
    EXPECT_NEAR(sim.state().vx[0], 0.0, 1e-12);
    // h k = 5 > 2: semi-implicit Euler's velocity error grows by |1 - h k| = 4 per step, and the
    // stability guard says so.
    Simulation euler(open_air(linear(1.0), Method::semi_implicit_euler, 0.05), {{{0, 0, 0}, {50, 50, 0}, m, 0.05}});
    euler.step_n(3);
    EXPECT_NEAR(std::abs(euler.state().vx[0]), 50.0 * 64.0, 1e-9);
    bool guarded = false;
    for (const Warning& w : euler.warnings()) guarded |= w.kind == WarningKind::stability;
    EXPECT_TRUE(guarded);
}

// A warning keeps its number, not its text (a big scene can warn for most particles); the text
// is made on demand and quotes the model's limits.
TEST(Drag, WarningsKeepTheirNumberAndSayItOnDemand) {
    EXPECT_LE(sizeof(Warning), 24u);
    // k = b / m = 100 1/s at dt = 0.05 s: dt k = 5, beyond semi-implicit Euler's limit of 2.
    Simulation euler(open_air(linear(1.0), Method::semi_implicit_euler, 0.05), {{{0, 0, 0}, {50, 50, 0}, 0.01, 0.05}});
    euler.step();
    const Warning* stiff = nullptr;
    for (const Warning& w : euler.warnings())
        if (w.kind == WarningKind::stability) stiff = &w;
    ASSERT_NE(stiff, nullptr);
    EXPECT_DOUBLE_EQ(stiff->value, 100.0);
    EXPECT_EQ(warning_message(*stiff, euler.model()),
              std::string("particle 0: dt * k = 5 exceeds the ") + to_string(Method::semi_implicit_euler) +
                  " stability limit 2 (drag stiffness k = 100 1/s); use dt <= 0.018 s or the exponential method");
    // 200 m/s through still air: Mach 0.58 at the monitor's first sample, the start state.
    Simulation fast(open_air(quadratic(0.47), Method::rk4, 0.001), {{{0, 0, 0}, {200, 0, 0}, 0.1, 0.05}});
    fast.step();
    bool mach = false;
    for (const Warning& w : fast.warnings()) {
        if (w.kind != WarningKind::mach) continue;
        mach = true;
        EXPECT_EQ(w.t, 0.0);
        EXPECT_EQ(w.value, 200.0);
        EXPECT_EQ(warning_message(w, fast.model()),
                  "particle 0: Mach 0.58 at t = 0.000 s; compressibility is not modelled (results unreliable above "
                  "Mach 0.3)");
    }
    EXPECT_TRUE(mach);
}

// The monitor keeps the scene's Reynolds range over its samples (every step for a few
// particles): the smallest and largest Re of any particle in flight, from the start state on.
TEST(Drag, ObservedReynoldsRangeSpansTheSamples) {
    const Model m = open_air(quadratic(0.47), Method::semi_implicit_euler, 0.002);
    Simulation still(m, {{{0, 0, 0}, {0, 0, 0}, 0.057, 0.033}});
    EXPECT_GT(still.observed_reynolds().lo, still.observed_reynolds().hi);  // nothing has moved yet
    // A lob whose speed dips at its apex, and a fast horizontal throw.
    Simulation sim(m, {{{0, 0, 0}, {2, 10, 0}, 0.057, 0.033}, {{0, 0, 0}, {30, 0, 5}, 0.057, 0.033}});
    double lo = INFINITY, hi = 0.0;
    auto sample = [&] {
        for (std::size_t i = 0; i < sim.particle_count(); ++i) {
            lo = std::min(lo, sim.reynolds_number(i));
            hi = std::max(hi, sim.reynolds_number(i));
        }
    };
    sample();
    for (int k = 0; k < 1500; ++k) {
        sim.step();
        sample();
    }
    EXPECT_DOUBLE_EQ(sim.observed_reynolds().lo, lo);
    EXPECT_DOUBLE_EQ(sim.observed_reynolds().hi, hi);
    // Re = speed * 2r / nu: the apex of the lob is slower than its 2 m/s horizontal start.
    const double re_per_speed = sim.state().drag_re_scale[0];
    EXPECT_LT(lo, 2.0 * re_per_speed);
    EXPECT_DOUBLE_EQ(hi, re_per_speed * std::sqrt(30.0 * 30.0 + 5.0 * 5.0));
}

TEST(Drag, VerticalQuadraticFallFollowsTanh) {
    // Falling from rest: v(t) = -v_t tanh(g t / v_t).
    const double m = 0.057, r = 0.033, cd = 0.47;
    const double c = 0.5 * 1.225 * cd * std::numbers::pi * r * r / m, vt = std::sqrt(g / c);
    Simulation sim(open_air(quadratic(cd), Method::rk4, 1e-3), {{{0, 0, 0}, {0, 0, 0}, m, r}});
    for (double t : {0.5, 1.0, 2.0, 4.0}) {
        sim.run_until(t);
        EXPECT_NEAR(sim.state().vy[0], -vt * std::tanh(g * t / vt), 1e-9) << t;
        // y(t) = -(v_t^2 / g) ln cosh(g t / v_t)
        EXPECT_NEAR(sim.state().y[0], -(vt * vt / g) * std::log(std::cosh(g * t / vt)), 1e-9) << t;
    }
}

TEST(Drag, VerticalQuadraticRiseFollowsTan) {
    // Rising: v(t) = v_t tan(atan(v0 / v_t) - g t / v_t) until the apex.
    const double m = 0.057, r = 0.033, cd = 0.47, v0 = 30.0;
    const double c = 0.5 * 1.225 * cd * std::numbers::pi * r * r / m, vt = std::sqrt(g / c);
    const double t_apex = vt / g * std::atan(v0 / vt);
    Simulation sim(open_air(quadratic(cd), Method::rk4, 1e-3), {{{0, 0, 0}, {0, v0, 0}, m, r}});
    for (double frac : {0.25, 0.5, 0.9}) {
        const double t = std::round(frac * t_apex * 1000) / 1000;
        sim.run_until(t);
        EXPECT_NEAR(sim.state().vy[0], vt * std::tan(std::atan(v0 / vt) - g * t / vt), 1e-8) << t;
    }
    // Apex height: (v_t^2 / 2g) ln(1 + v0^2 / v_t^2).
    Simulation apex(open_air(quadratic(cd), Method::dopri5, 1e-3), {{{0, 0, 0}, {0, v0, 0}, m, r}});
    double y_max = 0;
    while (apex.state().vy[0] > 0) {
        apex.step();
        y_max = std::max(y_max, apex.state().y[0]);
    }
    EXPECT_NEAR(y_max, vt * vt / (2 * g) * std::log(1 + v0 * v0 / (vt * vt)), 1e-4);
}

TEST(Drag, SphereCorrelationMatchesTabulatedValues) {
    // Standard drag curve of a smooth sphere (Clift, Grace & Weber, Bubbles, Drops and
    // Particles, 1978, Table 5.2; Schlichting, Boundary-Layer Theory, Fig. 1.21). Morrison's fit
    // is within ~10% below the crisis; past it the measurements themselves scatter by ~30%.
    struct Point { double re, cd, tolerance; };
    for (Point p : {Point{0.1, 244.0, 0.1}, {1.0, 26.5, 0.1}, {10.0, 4.15, 0.1}, {100.0, 1.09, 0.1},
                    {1e3, 0.47, 0.1}, {1e4, 0.41, 0.1}, {1e5, 0.47, 0.12}, {1e6, 0.15, 0.3}}) {
        EXPECT_NEAR(sphere_cd(p.re), p.cd, p.tolerance * p.cd) << "Re = " << p.re;
    }
    // Creeping flow limit is Stokes: Cd Re -> 24.
    EXPECT_NEAR(sphere_cd_times_re(1e-6), 24.0, 1e-3);
    // The drag crisis: Cd drops by more than half between Re = 2e5 and 5e5.
    EXPECT_LT(sphere_cd(5e5), 0.5 * sphere_cd(2e5));
}

TEST(Drag, StokesCoefficientFromViscosity) {
    DragSettings stokes{DragModel::linear, 0.47, std::nullopt};
    Air air;
    const DragCoefficients c = drag_coefficients(stokes, air, 2.0, 0.01);
    EXPECT_NEAR(c.k * 2.0, 6 * std::numbers::pi * air.viscosity_pa_s * 0.01, 1e-18);
}

TEST(Wind, ConstantWindIsAMovingAirFrame) {
    // A particle at rest in wind w behaves like one launched with -w in still air, seen from
    // a frame moving with the wind.
    const Vec3 w{4, 0, -2};
    Model windy = open_air(quadratic(0.47), Method::rk4, 1e-3);
    windy.world.wind.kind = WindKind::constant;
    windy.world.wind.velocity = w;
    Simulation a(windy, {{{0, 0, 0}, {0, 0, 0}, 0.057, 0.033}});
    Simulation b(open_air(quadratic(0.47), Method::rk4, 1e-3), {{{0, 0, 0}, -w, 0.057, 0.033}});
    a.run_until(1.5);
    b.run_until(1.5);
    const double t = 1.5;
    EXPECT_LT(glm::length(a.state().velocity(0) - (b.state().velocity(0) + w)), 1e-12);
    EXPECT_LT(glm::length(a.state().position(0) - (b.state().position(0) + w * t)), 1e-10);
}

TEST(Wind, WithoutDragWindIsNeverEvaluated) {
    Model m = open_air({DragModel::none, 0.47, std::nullopt}, Method::rk4, 1e-2);
    m.world.wind.kind = WindKind::gust;
    Simulation sim(m, {{{0, 0, 0}, {1, 2, 3}, 0.057, 0.033}});
    sim.step_n(100);
    EXPECT_EQ(sim.counters().gravity, 400u);
    EXPECT_EQ(sim.counters().drag, 0u);
    EXPECT_EQ(sim.counters().wind, 0u);
}

TEST(Wind, CountersShowOnlyEnabledTermsRun) {
    Model m = open_air(quadratic(0.47), Method::semi_implicit_euler, 1e-2);
    Simulation no_wind(m, {{{0, 0, 0}, {1, 2, 3}, 0.057, 0.033}});
    no_wind.step_n(10);
    EXPECT_EQ(no_wind.counters().drag, 10u);
    EXPECT_EQ(no_wind.counters().wind, 0u);
    m.world.wind.kind = WindKind::shear;
    m.world.wind.velocity = {3, 0, 0};
    Simulation sheared(m, {{{0, 0, 0}, {1, 2, 3}, 0.057, 0.033}});
    sheared.step_n(10);
    EXPECT_EQ(sheared.counters().wind, 10u);
}

TEST(Wind, GustIsBoundedAndReproducible) {
    WindSettings s;
    s.kind = WindKind::gust;
    s.velocity = {2, 0, 0};
    s.gust_amplitude = {1.5, 0.5, 1.0};
    const WindField a(s, Room{}), b(s, Room{});
    s.gust_seed = 2;
    const WindField c(s, Room{});
    bool differs = false;
    for (double t = 0; t < 60; t += 0.37) {
        const Vec3 w = a.at({0, 0, 0}, t);
        EXPECT_EQ(w, b.at({0, 0, 0}, t));
        differs |= w != c.at({0, 0, 0}, t);
        EXPECT_LE(std::abs(w.x - 2), 1.5);
        EXPECT_LE(std::abs(w.y), 0.5);
        EXPECT_LE(std::abs(w.z), 1.0);
    }
    EXPECT_TRUE(differs);
}

TEST(Wind, ShearGrowsWithHeightAsAPowerLaw) {
    WindSettings s;
    s.kind = WindKind::shear;
    s.velocity = {5, 0, 0};
    s.reference_height_m = 2.0;
    s.shear_exponent = 1.0 / 7.0;
    Room room;  // floor at y = -3
    const WindField f(s, room);
    EXPECT_NEAR(f.at({0, -1, 0}, 0).x, 5.0, 1e-12);
    EXPECT_NEAR(f.at({0, 1, 0}, 0).x, 5.0 * std::pow(2.0, 1.0 / 7.0), 1e-12);
    EXPECT_EQ(f.at({0, -3, 0}, 0).x, 0.0);
}

TEST(Wind, VortexSwirlsAroundItsAxis) {
    WindSettings s;
    s.kind = WindKind::vortex;
    s.vortex_max_speed = 3.0;
    s.vortex_core_radius_m = 1.0;
    const WindField f(s, Room{});
    const Vec3 w1 = f.at({1, 0, 0}, 0), w2 = f.at({2, 0, 0}, 0), w_in = f.at({0.5, 0, 0}, 0);
    EXPECT_NEAR(glm::length(w1), 3.0, 1e-12);
    EXPECT_NEAR(glm::length(w2), 1.5, 1e-12);
    EXPECT_NEAR(glm::length(w_in), 1.5, 1e-12);
    EXPECT_NEAR(glm::dot(w1, Vec3(1, 0, 0)), 0.0, 1e-12);  // tangential
}

}  // namespace
}  // namespace pl
