// Invariants of particle-particle collisions over many impacts: momentum to round-off, kinetic
// energy kept at e = 1 without friction and never gained otherwise, the energy ledger's residual,
// the same bits on one and two threads, and the impulse's own laws with spin and friction.
#include "physics/collide/collision_pass.hpp"
#include "physics/collide/narrow_phase.hpp"
#include "physics/model/emitter.hpp"
#include "physics/stepping/energy.hpp"
#include "physics/stepping/relaunch.hpp"
#include "physics/stepping/simulation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <random>

namespace pl {
namespace {

// n balls of 1 cm in a 1 m box without gravity or drag, frictionless elastic walls.
struct Gas {
    Model model;
    std::vector<ParticleSpec> particles;
};

Gas gas(std::size_t n, double restitution, double friction, std::uint64_t seed = 7) {
    Gas g;
    g.model.room.size = {1.0, 1.0, 1.0};
    g.model.world.gravity = {0.0, 0.0, 0.0};
    g.model.contact.restitution = 1.0;
    g.model.contact.friction = 0.0;
    g.model.integrator.dt = 1e-3;
    g.model.collisions = {true, restitution, friction};
    Emitter e;
    e.count = n;
    e.seed = seed;
    e.region_min = {-0.45, -0.45, -0.45};
    e.region_max = {0.45, 0.45, 0.45};
    e.speed_min = 0.5;
    e.speed_max = 2.0;
    e.radius_min = e.radius_max = 0.01;
    e.mass_min = 0.001;
    e.mass_max = 0.004;
    g.particles = emit_particles(e, g.model.room);
    return g;
}

Vec3 momentum(const ParticleState& s) {
    Vec3 p{0.0};
    for (std::size_t i = 0; i < s.size(); ++i) p += s.mass[i] * s.velocity(i);
    return p;
}

double kinetic(const ParticleState& s) {
    double e = 0.0;
    for (std::size_t i = 0; i < s.size(); ++i) e += kinetic_energy(s.mass[i], s.velocity(i));
    return e;
}

TEST(CollisionGas, ElasticGasKeepsItsEnergyAndLedger) {
    const Gas g = gas(1000, 1.0, 0.0);
    Simulation sim(g.model, g.particles);
    const double e0 = kinetic(sim.state());
    sim.run_until(2.0);
    EXPECT_GT(sim.collisions_total(), 2000u) << "too few collisions to test anything";
    EXPECT_NEAR(kinetic(sim.state()) / e0, 1.0, 1e-12);
    const EnergyBreakdown en = total_energy(sim.state(), sim.model().world.gravity, sim.model().room);
    EXPECT_NEAR(en.collision_work / e0, 0.0, 1e-12);
    EXPECT_NEAR(en.residual() / e0, 0.0, 1e-12);
}

TEST(CollisionGas, MomentumKeptToRoundOffAndEnergyNeverGained) {
    // Walls far away: only the collisions act; inelastic with friction, over many impacts.
    Gas g = gas(1000, 0.6, 0.3);
    g.model.room.size = {50.0, 50.0, 50.0};
    for (ParticleSpec& p : g.particles) p.velocity -= 1.5 * p.position;  // converging: a crowd of impacts
    Simulation sim(g.model, g.particles);
    const Vec3 p0 = momentum(sim.state());
    double scale = 0.0;
    for (const ParticleSpec& p : g.particles) scale += p.mass * glm::length(p.velocity);
    double last = kinetic(sim.state());
    for (int k = 0; k < 500; ++k) {
        sim.step();
        const double now = kinetic(sim.state());
        ASSERT_LE(now, last * (1 + 1e-14)) << "step " << k;
        last = now;
    }
    EXPECT_GT(sim.collisions_total(), 500u);
    EXPECT_LT(glm::length(momentum(sim.state()) - p0) / scale, 1e-14);
    const EnergyBreakdown en = total_energy(sim.state(), sim.model().world.gravity, sim.model().room);
    EXPECT_LT(en.collision_work, 0.0);
    EXPECT_NEAR(en.residual() / en.initial, 0.0, 1e-12);
}

bool has_pair_with(const Simulation& sim, std::uint32_t i) {
    const std::vector<collide::Pair>& pairs = sim.collision_pass()->candidates();
    return std::any_of(pairs.begin(), pairs.end(), [i](const collide::Pair& p) { return p.a == i || p.b == i; });
}

// The particles that take part change: one that freezes (a runaway) leaves the pairs at once,
// and relaunched it joins them again (the collision pass remakes its list of particles only
// when one froze or thawed, and the pair cache then runs the grid again).
TEST(CollisionGas, AFrozenParticleLeavesThePairsAndARelaunchedOneJoinsThem) {
    const Gas g = gas(2000, 1.0, 0.0);
    Simulation sim(g.model, g.particles);
    sim.step_n(30);
    const Vec3 x5 = sim.state().position(5);
    relaunch_particle(sim, 5, x5, {4e8, 0.0, 0.0});  // faster than light: frozen by its next step
    sim.step();
    ASSERT_TRUE(sim.state().frozen[5]);
    EXPECT_EQ(sim.state().position(5), x5);
    for (int k = 0; k < 20; ++k) {
        sim.step();
        ASSERT_FALSE(has_pair_with(sim, 5)) << "step " << k;
    }
    // Back, overlapping particle 7 (1.5 cm apart, radii 1 cm): the next step pairs them.
    const Vec3 x7 = sim.state().position(7);
    relaunch_particle(sim, 5, x7 + Vec3(x7.x > 0.0 ? -0.015 : 0.015, 0.0, 0.0), Vec3(0.0));
    sim.step();
    ASSERT_FALSE(sim.state().frozen[5]);
    const std::vector<collide::Pair>& pairs = sim.collision_pass()->candidates();
    EXPECT_NE(std::find(pairs.begin(), pairs.end(), collide::Pair{std::min(5u, 7u), std::max(5u, 7u)}), pairs.end());
}

TEST(CollisionGas, SameBitsOnOneAndTwoThreads) {
    const Gas g = gas(4096, 0.9, 0.2, 11);  // two particle ranges on two threads
    Simulation one(g.model, g.particles), two(g.model, g.particles);
    one.set_threads(1);
    two.set_threads(2);
    for (int k = 0; k < 100; ++k) one.step();
    two.step_n(100);
    EXPECT_GT(one.collisions_total(), 100u);
    EXPECT_EQ(one.collisions_total(), two.collisions_total());
    for (std::size_t i = 0; i < one.particle_count(); ++i) {
        ASSERT_EQ(one.state().position(i), two.state().position(i)) << i;
        ASSERT_EQ(one.state().velocity(i), two.state().velocity(i)) << i;
    }
}

TEST(CollisionImpulse, MomentumKeptEnergyNotGainedSlidingStopped) {
    using namespace collide;
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1.0, 1.0), pos(0.1, 1.0);
    int sticks = 0;
    for (int trial = 0; trial < 1000; ++trial) {
        Body a{{u(rng), u(rng), u(rng)}, {5 * u(rng), 5 * u(rng), 5 * u(rng)}, pos(rng), 0.1 * pos(rng), 0.4};
        Body b{{u(rng), u(rng), u(rng)}, {5 * u(rng), 5 * u(rng), 5 * u(rng)}, pos(rng), 0.1 * pos(rng), 2.0 / 3.0};
        a.moment *= a.mass * a.radius * a.radius;  // I = k m r^2: a solid and a hollow ball
        b.moment *= b.mass * b.radius * b.radius;
        const Vec3 n = glm::normalize(Vec3{u(rng), u(rng), u(rng)});
        const double e = 0.5 * (u(rng) + 1), mu = trial % 2 ? 10.0 : 0.2 * (u(rng) + 1);
        const ImpulseResult r = sphere_impulse(a, b, n, e, mu, true);
        if (!r.applied) continue;
        const Vec3 p_before = a.mass * a.velocity + b.mass * b.velocity;
        const Vec3 p_after = a.mass * (a.velocity + r.dv_a) + b.mass * (b.velocity + r.dv_b);
        EXPECT_LT(glm::length(p_after - p_before), 1e-14);
        auto energy = [](const Body& x, const Vec3& dv, const Vec3& dw) {
            return kinetic_energy(x.mass, x.velocity + dv) + 0.5 * x.moment * glm::dot(x.spin + dw, x.spin + dw);
        };
        const double before = energy(a, {}, {}) + energy(b, {}, {});
        const double after = energy(a, r.dv_a, r.dw_a) + energy(b, r.dv_b, r.dw_b);
        EXPECT_LE(after, before * (1 + 1e-13));
        // Separating at e times the approach speed along n.
        const Body a2{a.velocity + r.dv_a, a.spin + r.dw_a, a.mass, a.radius, a.moment};
        const Body b2{b.velocity + r.dv_b, b.spin + r.dw_b, b.mass, b.radius, b.moment};
        const Vec3 u0 = contact_velocity(a, b, n, true), u1 = contact_velocity(a2, b2, n, true);
        EXPECT_NEAR(glm::dot(u1, n), -e * glm::dot(u0, n), 1e-12);
        // Coulomb: either the slip stops (stick), or the friction impulse is mu J_n and the slip
        // keeps its direction (it never reverses).
        const Vec3 slip0 = u0 - glm::dot(u0, n) * n, slip1 = u1 - glm::dot(u1, n) * n;
        const double jn = glm::dot(r.impulse, n), jt = glm::length(r.impulse - jn * n);
        if (glm::length(slip1) > 1e-12) {
            EXPECT_NEAR(jt, mu * jn, 1e-12 * (1 + jn));
            EXPECT_GT(glm::dot(slip0, slip1), 0.0);
        } else {
            ++sticks;
        }
    }
    EXPECT_GT(sticks, 100);  // both regimes are exercised
}

TEST(CollisionImpulse, ElasticFrictionlessKeepsEnergyExactly) {
    using namespace collide;
    const Body a{{1.0, 0.2, 0.0}, {}, 0.3, 0.05, 0.4}, b{{-0.5, 0.0, 0.1}, {}, 0.7, 0.08, 0.4};
    const Vec3 n = glm::normalize(Vec3{1.0, 0.3, -0.2});
    const ImpulseResult r = sphere_impulse(a, b, n, 1.0, 0.0, false);
    ASSERT_TRUE(r.applied);
    const double before = kinetic_energy(a.mass, a.velocity) + kinetic_energy(b.mass, b.velocity);
    const double after = kinetic_energy(a.mass, a.velocity + r.dv_a) + kinetic_energy(b.mass, b.velocity + r.dv_b);
    EXPECT_NEAR(after, before, 1e-15);
}

TEST(CollisionImpulse, TimeOfImpactIsTheQuadraticsFirstRoot) {
    using namespace collide;
    // Centres 1 m apart on x, closing at 4 m/s with a 0.6 m sideways offset: |d + w s| = 1 at
    // (1 - 4 s)^2 + 0.36 = 1, s = (1 - 0.8) / 4.
    EXPECT_NEAR(time_of_impact({1.0, 0.6, 0.0}, {-4.0, 0.0, 0.0}, 1.0, 1.0), 0.05, 1e-15);
    EXPECT_EQ(time_of_impact({1.0, 1.2, 0.0}, {-4.0, 0.0, 0.0}, 1.0, 1.0), -1.0);  // passes by
    EXPECT_EQ(time_of_impact({3.0, 0.0, 0.0}, {-4.0, 0.0, 0.0}, 1.0, 0.4), -1.0);  // not within the step
    EXPECT_EQ(time_of_impact({0.5, 0.0, 0.0}, {-1.0, 0.0, 0.0}, 1.0, 1.0), 0.0);   // overlapping and closing
    EXPECT_EQ(time_of_impact({0.5, 0.0, 0.0}, {1.0, 0.0, 0.0}, 1.0, 1.0), -1.0);   // overlapping, separating
}

}  // namespace
}  // namespace pl
