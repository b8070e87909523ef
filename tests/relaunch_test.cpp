// Launching a particle again mid-run (the GUI's L key): new state, released from the wall it
// rested on, and an energy ledger whose residual still measures only the integrator's error.
#include "physics/stepping/energy.hpp"
#include "physics/stepping/relaunch.hpp"
#include "test_scenes.hpp"

#include <gtest/gtest.h>

namespace pl {
namespace {

using test::ball_at_height;
using test::drop_model;

double residual(const Simulation& sim) {
    return particle_energy(sim.state(), 0, sim.model().world.gravity, sim.model().room).residual();
}

TEST(Relaunch, RestingBallFliesAgainFromTheGivenState) {
    Simulation sim(drop_model(0.5, Method::semi_implicit_euler, 1e-3), {ball_at_height(1.0)});
    sim.run_until(5.0);
    ASSERT_NE(sim.state().resting[0] & (1u << Wall::y_min), 0) << "the ball should have come to rest";

    const Vec3 start{0.5, 2.0, -0.5}, velocity{1.0, -3.0, 0.5};  // even aimed at the floor
    relaunch_particle(sim, 0, start, velocity);
    EXPECT_EQ(sim.state().position(0), start);
    EXPECT_EQ(sim.state().velocity(0), velocity);
    EXPECT_EQ(sim.state().resting[0], 0);

    sim.step();
    // In flight under gravity: semi-implicit Euler's first step from the new state.
    const double h = sim.dt();
    EXPECT_DOUBLE_EQ(sim.state().vy[0], velocity.y - 9.81 * h);
    EXPECT_DOUBLE_EQ(sim.state().y[0], start.y + (velocity.y - 9.81 * h) * h);
}

TEST(Relaunch, EnergyPutInIsCreditedSoTheResidualDoesNotJump) {
    Simulation sim(drop_model(0.8, Method::rk4, 1e-3), {ball_at_height(2.0)});
    sim.run_until(1.0);
    const double before = residual(sim);
    relaunch_particle(sim, 0, {0.0, 6.0, 0.0}, {2.0, 5.0, 0.0});
    EXPECT_NEAR(residual(sim), before, 1e-12);
    sim.run_until(2.0);
    EXPECT_NEAR(residual(sim), before, 1e-6);  // RK4's own error over 1 s of free flight
}

}  // namespace
}  // namespace pl
