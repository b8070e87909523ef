// A light ball between a wall and a heavy ball that drives it in (a hammer on a nail against a
// wall): the impacts reach their strike cap, sequential impulses take a thousandth of the heavy
// ball's speed an iteration, and without the wall-anchored shock pass (contact_shock.cpp) the
// heavy ball drove through the light one, with no warning. Sideways under gravity too: the weight
// pass takes only contacts that carry weight.
#include "physics/stepping/energy.hpp"
#include "physics/stepping/simulation.hpp"
#include "test_scenes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace pl {
namespace {

struct Hammer {
    double dt, speed, restitution, gravity;
    Method method;
};

// A 2 m room; the light ball (50 g) touches the wall x = -1 at rest, the heavy one (1000 times
// heavier, the same size) comes at it along x. Both start 1 m up: under gravity they fall side
// by side, the contact between them horizontal.
Simulation hammer(const Hammer& h) {
    Model m = test::colliding_room(h.dt, h.method, h.restitution, 0.0, 0.0);
    m.world.gravity = {0.0, -h.gravity, 0.0};
    const double r = 0.02;
    return Simulation(m, {{{-1.0 + r, 1.0, 0.0}, {0.0, 0.0, 0.0}, 0.05, r},
                          {{-0.5, 1.0, 0.0}, {-h.speed, 0.0, 0.0}, 50.0, r}});
}

TEST(CollisionWallShock, AHeavyBallDrivenAtALightOneOnAWallStopsOnIt) {
    for (const Hammer h : {Hammer{1e-3, 10.0, 0.5, 0.0, Method::semi_implicit_euler},
                           Hammer{1e-3, 10.0, 0.5, 9.81, Method::semi_implicit_euler},
                           Hammer{1e-3, 10.0, 0.0, 0.0, Method::velocity_verlet},
                           Hammer{1e-4, 100.0, 0.0, 9.81, Method::semi_implicit_euler},
                           Hammer{1e-4, 100.0, 0.5, 0.0, Method::rk4}}) {
        SCOPED_TRACE(testing::Message() << "dt " << h.dt << ", " << h.speed << " m/s, e " << h.restitution << ", g "
                                        << h.gravity << ", method " << static_cast<int>(h.method));
        Simulation sim = hammer(h);
        const double e0 = total_energy(sim.state(), sim.model().world.gravity, sim.model().room).total_mechanical();
        const double contact = sim.state().radius[0] + sim.state().radius[1];
        double deepest = 0.0, most = e0;
        while (sim.time() < 0.2) {
            sim.step();
            const ParticleState& s = sim.state();
            // The heavy ball never gets past the light one (it did: light ball at the wall, heavy
            // ball beyond it), and never deep into it (it was 1.7 contact distances in).
            ASSERT_GT(s.x[1], s.x[0]) << "t = " << sim.time();
            deepest = std::max(deepest, 1.0 - glm::length(s.position(1) - s.position(0)) / contact);
            most = std::max(most, total_energy(s, sim.model().world.gravity, sim.model().room).total_mechanical());
        }
        EXPECT_LT(deepest, 0.05);  // in the step of the blow; opened after it
        EXPECT_LT(1.0 - glm::length(sim.state().position(1) - sim.state().position(0)) / contact, 0.01);
        EXPECT_LE(most, e0 * (1.0 + 1e-9)) << "energy from nowhere";
        // Stopped on the light ball or sent back, not still driving into the wall.
        EXPECT_GE(sim.state().vx[1], -1e-6);
    }
}

}  // namespace
}  // namespace pl
