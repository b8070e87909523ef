// Shock propagation (physics/collide/contact_shock.cpp): balls of very unequal masses resting on
// each other. Sequential impulses converge at a rate set by the mass ratio, so without it a column
// of alternating masses at 1 : 1000 sank into its light balls by a quarter of their radius and
// stayed there (the overlap removal, split by inverse mass, pushed each light ball up by one pair
// and down by the next).
#include "physics/collide/collision_pass.hpp"
#include "physics/stepping/energy.hpp"
#include "physics/stepping/simulation.hpp"
#include "test_scenes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace pl::test {
namespace {

// The deepest overlap of neighbours in a column, as a share of the smaller radius.
double deepest_in_column(const ParticleState& s) {
    double worst = 0.0;
    for (std::size_t k = 0; k + 1 < s.size(); ++k) {
        const double gap = glm::length(s.position(k + 1) - s.position(k)) - s.radius[k] - s.radius[k + 1];
        worst = std::max(worst, -gap / std::min(s.radius[k], s.radius[k + 1]));
    }
    return worst;
}

// Eight balls of 5 cm, masses 1 and `ratio` kg in turn from the floor up, `spacing` apart.
Pile column(double ratio, double spacing) {
    Pile p = pile(0, 1.0, 2.5);
    p.model.contact.restitution = 0.8;
    for (int k = 0; k < 8; ++k)
        p.particles.push_back({{0.0, 0.05 + spacing * k, 0.0}, {0.0, 0.0, 0.0}, k % 2 ? ratio : 1.0, 0.05});
    return p;
}

TEST(CollisionShock, AColumnAtOneToAThousandStandsWhereItWasPut) {
    const Pile p = column(1000.0, 0.1);  // touching, at rest
    Simulation sim(p.model, p.particles);
    sim.run_until(2.0);
    EXPECT_EQ(sim.asleep_count(), 8u);
    EXPECT_LT(deepest_in_column(sim.state()), 1e-3);  // was 0.26
    EXPECT_NEAR(sim.state().y[7], 0.75, 1e-3);
    const EnergyBreakdown en = total_energy(sim.state(), sim.model().world.gravity, sim.model().room);
    EXPECT_LT(std::abs(en.residual()), 1e-6 * en.initial) << en.residual() << " J";
}

TEST(CollisionShock, AColumnDroppedAtOneToAThousandSettlesWithoutSinking) {
    const Pile p = column(1000.0, 0.2);  // 10 cm gaps: each ball falls onto the one below
    Simulation sim(p.model, p.particles);
    sim.run_until(3.0);
    EXPECT_EQ(sim.asleep_count(), 8u);
    EXPECT_LT(deepest_in_column(sim.state()), 0.01);  // was 0.13
    const EnergyBreakdown en = total_energy(sim.state(), sim.model().world.gravity, sim.model().room);
    EXPECT_LT(std::abs(en.residual()), 1e-3 * en.initial) << en.residual() << " J";
    EXPECT_LE(en.collision_work, 0.0) << "the contacts and impacts gave energy";
}

TEST(CollisionShock, APileOfMassesSpreadOverThreeDecadesSettlesStill) {
    Pile p = pile(300, 0.3, 0.8, 7);
    std::uint64_t state = 12345;
    for (ParticleSpec& b : p.particles) {  // log-uniform masses from 1 g to 1 kg
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        b.mass = 1e-3 * std::pow(1e3, static_cast<double>(state >> 11) * 0x1p-53);
    }
    Simulation sim(p.model, p.particles);
    sim.run_until(1.0);
    EXPECT_TRUE(sim.collision_pass()->propagated_shock());
    sim.run_until(4.0);
    const ParticleState& s = sim.state();
    EXPECT_GT(sim.asleep_count(), s.size() * 95 / 100);
    EXPECT_LT(deepest_overlap(s), 0.01);
    const EnergyBreakdown en = total_energy(s, sim.model().world.gravity, sim.model().room);
    EXPECT_LT(std::abs(en.residual()) / en.initial, 0.01) << "residual " << en.residual() << " J";
    EXPECT_LT(en.collision_work, 0.0);
}

// Equal balls converge without it: a pile of them never takes the pass (their bits are those of
// the golden hashes).
TEST(CollisionShock, APileOfEqualBallsDoesNotPropagateShock) {
    const Pile p = pile(300, 0.3, 0.8, 7);
    Simulation sim(p.model, p.particles);
    bool shocked = false;
    for (int k = 0; k < 300; ++k) {
        sim.step();
        shocked = shocked || sim.collision_pass()->propagated_shock();
    }
    EXPECT_FALSE(shocked);
}

}  // namespace
}  // namespace pl::test
