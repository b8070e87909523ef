// The air model (physics/model/air_model.hpp) and the air column (terms/air_column.hpp):
// the International Standard Atmosphere against the U.S. Standard Atmosphere 1976 tables;
// every force term sees the air at the particle's height; added mass against closed forms
// (acceleration from rest, buoyant terminal speeds, the tanh fall); each method's order on a
// scene with ISA air, added mass, buoyancy and quadratic drag; the term is never evaluated when
// off; presets with the new fields round-trip.
#include "io/preset_io.hpp"
#include "physics/model/air_model.hpp"
#include "physics/model/drag.hpp"
#include "physics/stepping/simulation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace pl {
namespace {

constexpr double g = 9.81;

double volume(double radius) { return 4.0 / 3.0 * std::numbers::pi * radius * radius * radius; }

// U.S. Standard Atmosphere 1976 (NOAA-S/T 76-1562), Table I, by geometric altitude: density,
// dynamic viscosity, temperature and pressure as printed (5 significant digits; 0: not checked).
TEST(AirModel, IsaMatchesTheStandardAtmosphereTable) {
    struct Row {
        double h, rho, mu, t, p;
    };
    const Row table[] = {{0.0, 1.2250, 1.7894e-5, 288.150, 101325.0},
                         {1500.0, 1.0581, 0.0, 278.402, 0.0},
                         {3000.0, 0.90925, 1.6938e-5, 268.659, 70121.0}};
    for (const Row& r : table) {
        EXPECT_NEAR(isa_density(r.h), r.rho, 5e-5 * r.rho) << r.h;
        if (r.mu > 0) {
            EXPECT_NEAR(sutherland_viscosity(isa_temperature(r.h)), r.mu, 1e-4 * r.mu) << r.h;
        }
        EXPECT_NEAR(isa_temperature(r.h), r.t, 1e-3) << r.h;
        if (r.p > 0) {
            EXPECT_NEAR(isa_pressure(r.h), r.p, 1e-4 * r.p) << r.h;
        }
    }
    // The tropopause (geopotential 11 km, geometric 11019 m): 216.65 K, 22632 Pa.
    EXPECT_NEAR(isa_temperature(11019.0), 216.65, 2e-3);
    EXPECT_NEAR(isa_pressure(11019.0), 22632.0, 2.0);
    // Geopotential, not geometric, altitude in the formulas: at 3000 m the two differ by 1.4 m,
    // 1.2e-4 in density, above the table's rounding.
    const Air isa{1.225, 1.81e-5, AirModel::isa};
    EXPECT_EQ(air_density_at(isa, 3000.0), isa_density(3000.0));
    EXPECT_EQ(air_viscosity_at(isa, 3000.0), sutherland_viscosity(isa_temperature(3000.0)));
}

TEST(AirModel, DensityGradientIsTheDerivative) {
    for (const double h : {-400.0, 0.0, 2000.0, 9000.0, 12000.0}) {
        const double step = 0.5;
        const double central = (isa_density(h + step) - isa_density(h - step)) / (2 * step);
        EXPECT_NEAR(isa_density_gradient(h), central, 1e-7 * std::abs(central)) << h;
    }
}

TEST(AirModel, ConstantAirIgnoresTheAltitude) {
    const Air air{1.1, 1.7e-5, AirModel::constant, 3000.0};
    EXPECT_EQ(air_density_at(air, 5000.0), 1.1);
    EXPECT_EQ(air_viscosity_at(air, 5000.0), 1.7e-5);
    EXPECT_EQ(air_density_gradient_at(air, 5000.0), 0.0);
}

// A tall room; ISA air from the floor at `base` m.
Model column_scene(DragModel drag, double base, bool added_mass, bool buoyancy) {
    Model m;
    m.room.center = {0, 100, 0};
    m.room.size = {1000, 200, 1000};
    m.world.air.model = AirModel::isa;
    m.world.air.base_altitude_m = base;
    m.world.added_mass = added_mass;
    m.world.buoyancy = buoyancy;
    m.drag.model = drag;
    return m;
}

// A foam ball (1 g, R = 5 cm): buoyancy 64% and added mass 32% of its mass at sea level.
const ParticleSpec foam{{0, 150, 0}, {6, -3, 2}, 1e-3, 0.05, {0, 0, 40}};

// Every term (each drag model, buoyancy, Magnus lift) sees the density and viscosity at the
// particle's height, and the inertia is m + 1/2 rho V there: the ISA scene's acceleration equals
// the one in constant air of the local values, scaled by m / M, plus the change of M along the
// path (terms/air_column.hpp).
TEST(AirColumn, EveryTermSeesTheAirAtTheParticlesHeight) {
    for (const DragModel drag : {DragModel::linear, DragModel::quadratic, DragModel::sphere_re}) {
        Model isa = column_scene(drag, 2500.0, true, true);
        isa.drag.lift = LiftModel::sawicki;
        const double h = 2500.0 + (foam.position.y - isa.room.floor_y());
        Model constant = isa;
        constant.world.air = {isa_density(h), sutherland_viscosity(isa_temperature(h)), AirModel::constant};
        constant.world.added_mass = false;
        const Vec3 a_isa = Simulation(isa, {foam}).acceleration(0);
        const Vec3 a_free = Simulation(constant, {foam}).acceleration(0);
        const double inertial = foam.mass + 0.5 * isa_density(h) * volume(foam.radius);
        const double growth = 0.5 * volume(foam.radius) * isa_density_gradient(h) / inertial;
        const Vec3 v = foam.velocity;
        const Vec3 expected =
            (foam.mass / inertial) * a_free + growth * (0.5 * glm::dot(v, v) * Vec3(0, 1, 0) - v.y * v);
        EXPECT_NEAR(glm::length(a_isa - expected), 0.0, 1e-14 * glm::length(expected)) << to_string(drag);
        // And not the sea-level air's.
        Model sea = constant;
        sea.world.air = Air{};
        EXPECT_GT(glm::length(Simulation(sea, {foam}).acceleration(0) - a_free), 1e-3) << to_string(drag);
    }
}

Model still_air(bool added_mass, bool buoyancy, DragModel drag, Method method = Method::rk4) {
    Model m;
    m.room.center = {0, 500, 0};
    m.room.size = {100, 1000, 100};
    m.world.added_mass = added_mass;
    m.world.buoyancy = buoyancy;
    m.drag.model = drag;
    m.integrator.method = method;
    m.integrator.dt = 1e-3;
    return m;
}

const ParticleSpec dropped{{0, 900, 0}, {0, 0, 0}, 1e-3, 0.05};

// From rest (no drag yet): a0 = g (m - rho V) / (m + rho V / 2), without buoyancy g m / (m + rho V / 2).
TEST(AddedMass, AccelerationFromRest) {
    const double rho_v = 1.225 * volume(dropped.radius);
    for (const bool buoyancy : {false, true}) {
        const double a0 = g * (dropped.mass - (buoyancy ? rho_v : 0.0)) / (dropped.mass + 0.5 * rho_v);
        Simulation sim(still_air(true, buoyancy, DragModel::none), {dropped});
        EXPECT_NEAR(sim.acceleration(0).y, -a0, 1e-14 * a0);
        // Without drag the fall is uniformly accelerated, and RK4 follows it exactly.
        sim.step_n(2000);
        const double t = sim.time();
        EXPECT_NEAR(sim.state().y[0], 900.0 - 0.5 * a0 * t * t, 1e-10) << buoyancy;
    }
    Simulation plain(still_air(false, false, DragModel::none), {dropped});
    EXPECT_EQ(plain.acceleration(0).y, -g);
}

// Terminal speeds do not depend on the added mass (it only slows the approach): linear drag
// (m - rho V) g / b; quadratic sqrt(2 (m - rho V) g / (rho Cd A)), reached along
// v(t) = v_t tanh(a0 t / v_t), drop (v_t^2 / a0) ln cosh(a0 t / v_t), a0 from AccelerationFromRest.
TEST(AddedMass, BuoyantTerminalSpeedsAndTheTanhFall) {
    const double rho = 1.225, rho_v = rho * volume(dropped.radius);
    Model linear = still_air(true, true, DragModel::linear);
    linear.drag.linear_b = 2e-3;  // time constant M / b = 0.66 s
    Simulation slow(linear, {dropped});
    slow.run_until(25.0);
    const double v_linear = (dropped.mass - rho_v) * g / 2e-3;
    EXPECT_NEAR(-slow.state().vy[0], v_linear, 1e-9 * v_linear);

    Simulation quadratic(still_air(true, true, DragModel::quadratic), {dropped});
    const double area = std::numbers::pi * dropped.radius * dropped.radius;
    const double v_t = std::sqrt(2.0 * (dropped.mass - rho_v) * g / (rho * 0.47 * area));
    const double a0 = g * (dropped.mass - rho_v) / (dropped.mass + 0.5 * rho_v);
    quadratic.run_until(1.0);
    const double t = quadratic.time();
    EXPECT_NEAR(-quadratic.state().vy[0], v_t * std::tanh(a0 * t / v_t), 1e-10 * v_t);
    EXPECT_NEAR(900.0 - quadratic.state().y[0], v_t * v_t / a0 * std::log(std::cosh(a0 * t / v_t)), 1e-10);
    // The same ball without the added mass is measurably ahead at 1 s.
    Simulation light(still_air(false, true, DragModel::quadratic), {dropped});
    light.run_until(1.0);
    EXPECT_GT(quadratic.state().y[0] - light.state().y[0], 0.05);
}

// Each method keeps its order on a scene with ISA air, added mass, buoyancy and quadratic drag
// (no walls): end-point velocity error against a fine RK4 reference.
Model ordered_scene(Method method, double dt) {
    Model m = column_scene(DragModel::quadratic, 2000.0, true, true);
    m.integrator.method = method;
    m.integrator.dt = dt;
    m.integrator.adaptive = false;
    return m;
}

// A 4 g foam ball, R = 5 cm: the drag's stiffness 2 k |v| stays below 16 1/s, inside every
// method's stable and asymptotic range at the steps below.
const ParticleSpec thrown{{0, 20, 0}, {8, 12, 3}, 4e-3, 0.05};
constexpr double flight = 1.2;

double error_at(Method method, double dt) {
    static const Vec3 reference = [] {
        Simulation ref(ordered_scene(Method::rk4, 1e-4), {thrown});
        ref.run_until(flight);
        return ref.state().velocity(0);
    }();
    Simulation sim(ordered_scene(method, dt), {thrown});
    sim.run_until(flight);
    return glm::length(sim.state().velocity(0) - reference);
}

TEST(AirColumn, EachMethodKeepsItsOrder) {
    struct Case {
        Method method;
        double dt, order, tolerance;
    };
    const Case cases[] = {{Method::explicit_euler, 0.01, 1.0, 0.15},
                          {Method::semi_implicit_euler, 0.01, 1.0, 0.15},
                          {Method::velocity_verlet, 0.01, 2.0, 0.15},
                          {Method::rk4, 0.02, 4.0, 0.2},
                          {Method::exponential, 0.01, 1.0, 0.15}};  // through Forces::linearise
    for (const Case& c : cases) {
        const double observed = std::log2(error_at(c.method, c.dt) / error_at(c.method, c.dt / 2));
        EXPECT_NEAR(observed, c.order, c.tolerance) << to_string(c.method);
    }
    // Dormand-Prince at a fixed step: at least fifth order (its leading constant is tiny, so the
    // slope approaches 5 from above, see integrator_order_test.cpp).
    EXPECT_GT(std::log2(error_at(Method::dopri5, 0.1) / error_at(Method::dopri5, 0.05)), 4.8);
}

TEST(AirColumn, NeverEvaluatedWhenOffAndRunsOnTheGenericKernel) {
    Model off = still_air(false, true, DragModel::quadratic);
    Model on = ordered_scene(Method::semi_implicit_euler, 1e-3);
    EXPECT_FALSE(needs_generic_kernel(off));
    EXPECT_TRUE(needs_generic_kernel(on));
    Simulation a(off, {dropped}), b(on, {thrown});
    a.step_n(100);
    b.step_n(100);
    EXPECT_EQ(a.counters().air_column, 0u);
    EXPECT_GT(a.counters().fast_path, 0u);
    EXPECT_EQ(b.counters().air_column, b.counters().gravity);
    EXPECT_EQ(b.counters().fast_path, 0u);  // asked for the fast kernel, given the generic one
}

TEST(AirColumn, PresetFieldsRoundTrip) {
    Scene s;
    s.world.air.model = AirModel::isa;
    s.world.air.base_altitude_m = 2345.5;
    s.world.added_mass = true;
    Variant v;
    v.label = "sea level";
    v.air = Air{1.225, 1.81e-5, AirModel::isa, -120.25};
    s.variants = {v};
    s.particles = {{{0, 0, 0}, {6, -3, 2}, 1e-3, 0.05}};
    const LoadResult r = parse_preset(serialize_preset(s));
    ASSERT_TRUE(r.ok()) << r.error_text();
    EXPECT_EQ(r.scene->world.air.model, AirModel::isa);
    EXPECT_EQ(r.scene->world.air.base_altitude_m, 2345.5);
    EXPECT_TRUE(r.scene->world.added_mass);
    EXPECT_EQ(model_for_variant(*r.scene, 0).world.air.base_altitude_m, -120.25);
    EXPECT_EQ(serialize_preset(*r.scene), serialize_preset(s));
}

}  // namespace
}  // namespace pl
