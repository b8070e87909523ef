// Momentum over a million collisions: the collision pass (physics/collide/collision_pass.hpp) alone
// on an endless elastic gas. The particles fly freely and wrap around a periodic cube between
// steps (no walls: nothing else can change the momentum), so collisions never run out; the total
// momentum stays at its start to round-off and, at e = 1 without friction, so does the energy.
#include "physics/collide/collision_pass.hpp"
#include "physics/stepping/energy.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace pl {
namespace {

TEST(CollisionMomentum, KeptToRoundOffOverAMillionCollisions) {
    const std::size_t n = 2000;
    const double side = 0.4, radius = 0.01, h = 1e-3;
    Model m;
    m.room.size = {100.0, 100.0, 100.0};  // the walls stay far from the periodic cube
    m.world.gravity = {0.0, 0.0, 0.0};     // every closing pair is an impact
    m.collisions = {true, 1.0, 0.0};
    ParticleState s;
    s.resize(n);
    s.collision_work.assign(n, 0.0);
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> pos(-side / 2, side / 2), vel(-5.0, 5.0), mass(0.001, 0.004);
    for (std::size_t i = 0; i < n; ++i) {
        s.set_position(i, {pos(rng), pos(rng), pos(rng)});
        s.set_velocity(i, {vel(rng), vel(rng), vel(rng)});
        s.mass[i] = s.inertial_mass[i] = mass(rng);  // no added mass
        s.radius[i] = radius;
        s.inertia[i] = 0.4;
    }
    auto momentum = [&] {
        Vec3 p{0.0};
        for (std::size_t i = 0; i < n; ++i) p += s.mass[i] * s.velocity(i);
        return p;
    };
    auto kinetic = [&] {
        double e = 0.0;
        for (std::size_t i = 0; i < n; ++i) e += kinetic_energy(s.mass[i], s.velocity(i));
        return e;
    };
    const Vec3 p0 = momentum();
    const double e0 = kinetic();
    double scale = 0.0;
    for (std::size_t i = 0; i < n; ++i) scale += s.mass[i] * glm::length(s.velocity(i));
    collide::CollisionPass pass(n);
    std::uint64_t collisions = 0;
    int steps = 0;
    while (collisions < 1000000 && steps < 20000) {
        for (std::size_t i = 0; i < n; ++i) {  // wrap between steps, so no path crosses the cube
            Vec3 x = s.position(i);
            for (int k = 0; k < 3; ++k) x[k] -= side * std::floor(x[k] / side + 0.5);
            s.set_position(i, x);
        }
        pass.begin_step(s, m);
        for (std::size_t i = 0; i < n; ++i) s.set_position(i, s.position(i) + h * s.velocity(i));
        collisions += pass.end_step(s, m, h);
        ++steps;
    }
    EXPECT_GE(collisions, 1000000u) << "in " << steps << " steps";
    EXPECT_LT(glm::length(momentum() - p0) / scale, 1e-13);
    EXPECT_NEAR(kinetic() / e0, 1.0, 1e-11);
}

}  // namespace
}  // namespace pl
