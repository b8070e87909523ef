// A struck particle's new path leaves the swept box the broad phase paired it by
// (physics/collide/path_reach.cpp): the particles it reaches there are paired in the same step.
#include "physics/collide/collision_pass.hpp"
#include "physics/stepping/energy.hpp"
#include "physics/stepping/simulation.hpp"
#include "test_scenes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace pl {
namespace {

double deepest_overlap(const ParticleState& s) {
    double deepest = 0.0;
    for (std::size_t i = 0; i < s.size(); ++i)
        for (std::size_t j = i + 1; j < s.size(); ++j) {
            const double contact = s.radius[i] + s.radius[j];
            deepest = std::max(deepest, 1.0 - glm::distance(s.position(i), s.position(j)) / contact);
        }
    return deepest;
}

// Pool balls in a row 0.1 mm apart, struck along it at 8 m/s (elastic, frictionless, no
// gravity): the row is a Newton's cradle with gaps. Each ball's box, at rest, misses its
// neighbour's by the gap, so each pair is met only through the struck ball's new path. The blow
// crosses the row in 5 x 0.1 mm / 8 m/s = 63 us, inside the step of the first impact. Before the
// struck ball's new path was paired, the row took a ball a step, each pushed into the next
// unseen (14% of the contact distance at dt = 1 ms, 70% at 5 ms) with no warning.
TEST(CollisionReach, ARowWithGapsPassesTheBlowOnInsideTheStep) {
    const double r = 0.0286, gap = 1e-4, speed = 8.0;
    for (const double dt : {5e-4, 1e-3, 2e-3, 5e-3}) {
        SCOPED_TRACE("dt " + testing::PrintToString(dt));
        Model m = test::colliding_room(dt, Method::velocity_verlet, 1.0, 0.0, 0.0);
        m.world.gravity = Vec3(0.0);
        std::vector<ParticleSpec> balls{{{-0.5, 1.0, 0.0}, {speed, 0.0, 0.0}, 0.17, r}};
        for (int i = 0; i < 5; ++i) balls.push_back({{-0.3 + i * (2 * r + gap), 1.0, 0.0}, {0.0, 0.0, 0.0}, 0.17, r});
        Simulation sim(m, balls);
        const double e0 = total_energy(sim.state(), m.world.gravity, m.room).initial;
        while (sim.collisions_total() == 0) {
            sim.step();
            ASSERT_LT(sim.time(), 0.1);
        }
        // The step of the first impact took all five.
        EXPECT_EQ(sim.collisions_total(), 5u);
        EXPECT_GT(sim.collision_pass()->added_pairs(), 0u);
        const ParticleState& s = sim.state();
        for (std::size_t i = 0; i < 5; ++i) EXPECT_NEAR(glm::length(s.velocity(i)), 0.0, 1e-12) << i;
        EXPECT_NEAR(s.vx[5], speed, 1e-12);
        EXPECT_LT(deepest_overlap(s), 1e-9);
        // Then, to the wall and back through the row: never in each other, energy kept.
        for (int k = 0; k < 200; ++k) {
            sim.step();
            ASSERT_LT(deepest_overlap(sim.state()), 1e-9) << "step " << k;
        }
        EXPECT_TRUE(sim.warnings().empty());
        const EnergyBreakdown en = total_energy(sim.state(), m.world.gravity, m.room);
        EXPECT_NEAR(en.kinetic, e0, 1e-12 * e0);
    }
}

// A struck ball reaches one that its box at rest did not meet: a cue ball strikes A squarely
// along x, and A goes on into B, 0.5 mm beyond it. With a long step (10 ms: A moves up to 4 cm
// on) the pair A-B exists only through A's new path, on semi-implicit Euler too.
TEST(CollisionReach, AStruckBallMeetsABallItsBoxAtRestDidNot) {
    const double r = 0.02;
    Model m = test::colliding_room(0.01, Method::semi_implicit_euler, 1.0, 0.0, 0.0);
    m.world.gravity = Vec3(0.0);
    Simulation sim(m, {{{-0.5, 1.0, 0.0}, {4.0, 0.0, 0.0}, 0.1, r},
                       {{0.0, 1.0, 0.0}, {0.0, 0.0, 0.0}, 0.1, r},
                       {{2 * r + 5e-4, 1.0, 0.0}, {0.0, 0.0, 0.0}, 0.1, r}});
    while (sim.collisions_total() == 0) sim.step();
    EXPECT_EQ(sim.collisions_total(), 2u);
    EXPECT_NEAR(sim.state().vx[0], 0.0, 1e-12);
    EXPECT_NEAR(sim.state().vx[1], 0.0, 1e-12);
    EXPECT_NEAR(sim.state().vx[2], 4.0, 1e-12);
    EXPECT_LT(deepest_overlap(sim.state()), 1e-9);
}

}  // namespace
}  // namespace pl
