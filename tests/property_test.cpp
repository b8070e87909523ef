// Invariants over many random scenes (seeded, deterministic): never outside the room, never
// NaN, no energy from nowhere, and every lossy particle reaches a true standstill.
#include "physics/stepping/contact.hpp"
#include "physics/stepping/energy.hpp"
#include "physics/model/random.hpp"
#include "physics/stepping/simulation.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace pl {
namespace {

struct RandomScene {
    Model model;
    std::vector<ParticleSpec> particles;
};

RandomScene random_scene(std::uint64_t seed, bool allow_wind) {
    SplitMix64 rng(seed);
    RandomScene s;
    Model& m = s.model;
    m.room.center = {rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(-5, 5)};
    m.room.size = {rng.uniform(0.5, 4), rng.uniform(0.5, 4), rng.uniform(0.5, 4)};
    m.contact.restitution = rng.uniform01() < 0.2 ? 0.0 : rng.uniform(0.0, 0.9);
    m.contact.friction = rng.uniform(0.05, 0.8);
    m.contact.rest_speed = 0.05;
    const Method methods[] = {Method::semi_implicit_euler, Method::velocity_verlet, Method::rk4, Method::dopri5,
                              Method::exponential};
    m.integrator.method = methods[rng.next() % 5];
    m.integrator.dt = std::pow(10.0, rng.uniform(-3.5, -2.0));
    m.drag.model = static_cast<DragModel>(rng.next() % 4);
    m.drag.linear_b = rng.uniform01() < 0.5 ? std::optional<double>(rng.uniform(0.0, 0.01)) : std::nullopt;
    if (allow_wind && rng.uniform01() < 0.5) {
        m.world.wind.kind = static_cast<WindKind>(1 + rng.next() % 4);
        m.world.wind.velocity = {rng.uniform(-3, 3), 0, rng.uniform(-3, 3)};
    }
    const int n = 1 + static_cast<int>(rng.next() % 6);
    const Vec3 lo = m.room.min_corner(), hi = m.room.max_corner();
    for (int i = 0; i < n; ++i) {
        ParticleSpec p;
        p.radius = rng.uniform(0.01, 0.2);
        p.mass = rng.uniform(0.01, 1.0);
        for (int a = 0; a < 3; ++a) p.position[a] = rng.uniform(lo[a] + p.radius, hi[a] - p.radius);
        p.velocity = {rng.uniform(-20, 20), rng.uniform(-20, 20), rng.uniform(-20, 20)};
        s.particles.push_back(p);
    }
    return s;
}

bool finite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

TEST(Property, NeverOutsideTheRoomNeverNaN) {
    for (std::uint64_t seed = 1; seed <= 60; ++seed) {
        const RandomScene rs = random_scene(seed, true);
        Simulation sim(rs.model, rs.particles);
        const RoomBounds room(rs.model.room);
        for (int k = 0; k < 1500; ++k) {
            sim.step();
            const ParticleState& st = sim.state();
            for (std::size_t i = 0; i < st.size(); ++i) {
                ASSERT_TRUE(finite(st.position(i)) && finite(st.velocity(i))) << "seed " << seed;
                for (int w = 0; w < wall_count; ++w)
                    ASSERT_GE(room.distance(w, st.position(i), st.radius[i]), -1e-9)
                        << "seed " << seed << " particle " << i << " wall " << wall_name(w);
            }
        }
        EXPECT_TRUE(sim.warnings().empty() || sim.warnings().front().kind != WarningKind::frozen) << seed;
    }
}

TEST(Property, MechanicalEnergyNeverGrowsWithoutAnEnergySource) {
    for (std::uint64_t seed = 100; seed < 160; ++seed) {
        const RandomScene rs = random_scene(seed, false);
        Simulation sim(rs.model, rs.particles);
        const Vec3 g = rs.model.world.gravity;
        const double e0 = total_energy(sim.state(), g, rs.model.room).total_mechanical();
        for (int k = 0; k < 1500; ++k) {
            sim.step();
            const double e = total_energy(sim.state(), g, rs.model.room).total_mechanical();
            ASSERT_LE(e, e0 * (1 + 1e-9) + 1e-12) << "seed " << seed << " method "
                                                  << to_string(rs.model.integrator.method) << " step " << k;
        }
    }
}

TEST(Property, LossyParticlesComeToATrueStandstill) {
    for (std::uint64_t seed = 200; seed < 240; ++seed) {
        const RandomScene rs = random_scene(seed, false);
        Simulation sim(rs.model, rs.particles);
        sim.run_until(120.0);
        for (std::size_t i = 0; i < sim.particle_count(); ++i) {
            EXPECT_EQ(sim.state().velocity(i), Vec3(0.0)) << "seed " << seed << " particle " << i;
            EXPECT_NE(sim.state().resting[i], 0) << "seed " << seed << " particle " << i;
        }
        // And stays exactly there: no jitter.
        const ParticleState before = sim.state();
        sim.step_n(200);
        for (std::size_t i = 0; i < sim.particle_count(); ++i)
            EXPECT_EQ(sim.state().position(i), before.position(i)) << "seed " << seed;
    }
}

}  // namespace
}  // namespace pl
