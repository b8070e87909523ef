// Buoyancy, the first term added through the term list (physics/model/terms/buoyancy.hpp):
// closed forms (free fall with a = g (1 - rho V / m); terminal speed with linear drag
// v_t = (m - rho V) g / b), its work in the energy ledger's air-work line (the residual stays
// the method's error), and its counter (never evaluated when off).
#include "physics/stepping/energy.hpp"
#include "physics/stepping/simulation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace pl {
namespace {

constexpr double rho = 1.225;

// A tall room, one light ball (a table-tennis ball: 2.7 g, R = 2 cm) far from every wall.
Model tall_room(Method method, bool buoyancy) {
    Model m;
    m.room.center = {0, 500, 0};
    m.room.size = {100, 1000, 100};
    m.world.air.density_kg_m3 = rho;
    m.world.buoyancy = buoyancy;
    m.integrator.method = method;
    m.integrator.dt = 1e-3;
    return m;
}

ParticleSpec ball() { return {{0, 900, 0}, {0, 0, 0}, 2.7e-3, 0.02}; }

double displaced_mass(const ParticleSpec& p) { return rho * 4.0 / 3.0 * std::numbers::pi * std::pow(p.radius, 3); }

TEST(Buoyancy, FreeFallIsSlowedByTheWeightOfTheDisplacedAir) {
    for (const KernelChoice kernel : {KernelChoice::fast, KernelChoice::generic}) {
        Simulation sim(tall_room(Method::rk4, true), {ball()});
        sim.set_kernel(kernel);
        sim.step_n(2000);
        const ParticleSpec p = ball();
        const double g_eff = 9.81 * (1.0 - displaced_mass(p) / p.mass);
        const double t = sim.time();
        EXPECT_NEAR(sim.state().vy[0], -g_eff * t, 1e-12 * g_eff * t);
        EXPECT_NEAR(sim.state().y[0], 900.0 - 0.5 * g_eff * t * t, 1e-10);
        // Lighter than plain gravity would make it: the term is on.
        EXPECT_GT(sim.state().vy[0], -9.81 * t * (1.0 - 1e-3));
    }
}

TEST(Buoyancy, TerminalSpeedWithLinearDrag) {
    for (const Method method : {Method::rk4, Method::exponential}) {
        Model m = tall_room(method, true);
        m.drag.model = DragModel::linear;
        const double b = 5e-3;  // N s/m: time constant m / b = 0.54 s
        m.drag.linear_b = b;
        Simulation sim(m, {ball()});
        sim.step_n(15000);  // 28 time constants
        const ParticleSpec p = ball();
        const double v_t = (p.mass - displaced_mass(p)) * 9.81 / b;
        EXPECT_NEAR(-sim.state().vy[0], v_t, 1e-9 * v_t) << to_string(method);
    }
}

TEST(Buoyancy, ItsWorkIsInTheAirWorkLineAndTheResidualStaysTheMethodsError) {
    Model m = tall_room(Method::rk4, true);
    m.drag.model = DragModel::quadratic;
    Simulation sim(m, {ball()});
    sim.step_n(3000);
    const EnergyBreakdown e = total_energy(sim.state(), m.world.gravity, m.room);
    // Buoyancy lifts while the ball falls by dh: its work is -rho V g dh.
    const double dh = 900.0 - sim.state().y[0];
    EXPECT_NEAR(e.wind_work, -displaced_mass(ball()) * 9.81 * dh, 1e-9 * displaced_mass(ball()) * 9.81 * dh);
    EXPECT_LT(std::abs(e.residual()), 1e-10 * e.initial);
    // Without the line the residual would be the whole work.
    EXPECT_GT(std::abs(e.wind_work), 1e6 * std::abs(e.residual()));
    // And a first-order method's residual halves with the step (order 1).
    double residual[2];
    for (int k = 0; k < 2; ++k) {
        Model mk = tall_room(Method::explicit_euler, true);
        mk.integrator.dt = k == 0 ? 2e-3 : 1e-3;
        Simulation s(mk, {ball()});
        s.run_until(2.0);
        residual[k] = total_energy(s.state(), mk.world.gravity, mk.room).residual();
    }
    EXPECT_NEAR(residual[0] / residual[1], 2.0, 0.05);
}

TEST(Buoyancy, NotEvaluatedWhenOff) {
    for (const KernelChoice kernel : {KernelChoice::fast, KernelChoice::generic}) {
        for (const Method method : {Method::semi_implicit_euler, Method::dopri5, Method::exponential}) {
            Simulation off(tall_room(method, false), {ball()});
            Simulation on(tall_room(method, true), {ball()});
            off.set_kernel(kernel);
            on.set_kernel(kernel);
            off.step_n(100);
            on.step_n(100);
            EXPECT_EQ(off.counters().buoyancy, 0u);
            EXPECT_GT(off.counters().gravity, 0u);
            EXPECT_EQ(on.counters().buoyancy, on.counters().gravity) << to_string(method);
        }
    }
}

}  // namespace
}  // namespace pl
