// The energy ledger balances: E0 + wind work = KE + PE + dissipated + residual, with a small
// residual that does not drift when bounces are located exactly.
#include "physics/stepping/energy.hpp"
#include "physics/stepping/simulation.hpp"
#include "test_scenes.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace pl {
namespace {

Model lively_room(Method method, double dt) {
    Model m = test::drop_model(0.8, method, dt, 0.05);
    m.contact.friction = 0.3;
    m.drag.model = DragModel::quadratic;
    return m;
}

const std::vector<ParticleSpec> throws{{{0, 2, 0}, {3, 4, 1}, 0.057, 0.033}, {{1, 5, -1}, {-6, 0, 2}, 0.057, 0.033}};

TEST(EnergyLedger, ResidualIsSmallAndDoesNotDrift) {
    Simulation sim(lively_room(Method::rk4, 1e-3), throws);
    const Model& m = sim.model();
    double worst_early = 0, worst_late = 0;
    for (int k = 1; k <= 20000; ++k) {
        sim.step();
        const EnergyBreakdown e = total_energy(sim.state(), m.world.gravity, m.room);
        (k <= 10000 ? worst_early : worst_late) = std::max(k <= 10000 ? worst_early : worst_late, std::abs(e.residual()));
    }
    const EnergyBreakdown e = total_energy(sim.state(), m.world.gravity, m.room);
    EXPECT_GT(e.dissipated_bounce, 0.1 * e.initial);
    EXPECT_GT(e.dissipated_drag, 0.0);
    EXPECT_GT(e.dissipated_friction, 0.0);
    EXPECT_LT(worst_late, 1e-4 * e.initial);
    EXPECT_LT(worst_late, 2 * worst_early + 1e-12);
}

TEST(EnergyLedger, ResidualShrinksWithTheStepForFirstOrderMethods) {
    double previous = INFINITY;
    for (double dt : {4e-3, 1e-3, 2.5e-4}) {
        Simulation sim(lively_room(Method::semi_implicit_euler, dt), throws);
        sim.run_until(1.0);
        const double r = std::abs(total_energy(sim.state(), sim.model().world.gravity, sim.model().room).residual());
        EXPECT_LT(r, previous / 2.5) << dt;
        previous = r;
    }
}

TEST(EnergyLedger, WindWorkEntersTheBalance) {
    Model m = lively_room(Method::rk4, 1e-3);
    m.world.wind.kind = WindKind::constant;
    m.world.wind.velocity = {8, 0, 0};
    Simulation sim(m, throws);
    sim.run_until(2.0);
    const EnergyBreakdown e = total_energy(sim.state(), m.world.gravity, m.room);
    EXPECT_GT(e.wind_work, 0.0);
    EXPECT_LT(std::abs(e.residual()), 1e-5 * e.initial);
}

}  // namespace
}  // namespace pl
