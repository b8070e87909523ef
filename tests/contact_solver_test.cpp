// The contact solver's memory layout (physics/collide/contact_solver.hpp): its bodies are laid out
// in an order of space and each colour's contacts taken in that order, which must change no bit
// of the result. A heaped, still-moving pile is solved with its bodies in the broad phase's order,
// in index order, reversed and shuffled: the same velocities, positions, work and impulses.
#include "physics/collide/collision_pass.hpp"
#include "physics/collide/contact_solver.hpp"
#include "physics/stepping/simulation.hpp"

#include "test_scenes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>

namespace pl {
namespace {

// 600 balls of 2 cm dropped onto a 0.3 m floor, stepped until they are heaped but not asleep:
// thousands of contacts in a dozen colours or more.
Simulation heaped_pile() {
    const test::Pile p = test::pile(600, 0.3, 0.6, 3);
    Simulation sim(p.model, p.particles);
    sim.run_until(0.5);
    return sim;
}

struct Solved {
    ParticleState state;
    std::vector<collide::SolverContact> contacts;
};

Solved solve_with(const Simulation& sim, const std::vector<std::uint32_t>& space_order, std::size_t threads) {
    const collide::CollisionPass& pass = *sim.collision_pass();
    Solved out{sim.state(), {}};
    ParticleState& s = out.state;
    std::vector<Vec3> start_velocity(s.size()), start_spin(s.size());
    for (std::uint32_t i = 0; i < s.size(); ++i) {
        start_velocity[i] = s.velocity(i);
        start_spin[i] = s.spin(i);
    }
    const double h = sim.model().integrator.dt;
    collide::ContactSolver solver;
    solver.gather(s, sim.model(), pass.candidates(), {}, {}, pass.asleep(), h, collide::CollisionPass::impact_speed(sim.model(), h),
                  threads);
    solver.solve(s, sim.model(), h, start_velocity, start_spin, space_order, threads);
    out.contacts = solver.contacts();
    return out;
}

void expect_same(const Solved& x, const Solved& y, const char* what) {
    ASSERT_EQ(x.contacts.size(), y.contacts.size()) << what;
    for (std::size_t k = 0; k < x.contacts.size(); ++k) {
        ASSERT_EQ(x.contacts[k].lambda_n, y.contacts[k].lambda_n) << what << ", contact " << k;
        ASSERT_EQ(x.contacts[k].lambda_t, y.contacts[k].lambda_t) << what << ", contact " << k;
    }
    for (std::uint32_t i = 0; i < x.state.size(); ++i) {
        ASSERT_EQ(x.state.velocity(i), y.state.velocity(i)) << what << ", particle " << i;
        ASSERT_EQ(x.state.position(i), y.state.position(i)) << what << ", particle " << i;
        ASSERT_EQ(x.state.collision_work[i], y.state.collision_work[i]) << what << ", particle " << i;
    }
}

TEST(ContactSolver, TheOrderOfItsBodiesInMemoryChangesNoBit) {
    const Simulation sim = heaped_pile();
    ASSERT_LT(sim.asleep_count(), sim.particle_count()) << "the pile must still be awake";
    const std::vector<std::uint32_t>& space = sim.collision_pass()->pair_cache().grid().order();
    ASSERT_EQ(space.size(), sim.particle_count());
    std::vector<std::uint32_t> ids(sim.particle_count());
    std::iota(ids.begin(), ids.end(), 0u);
    std::vector<std::uint32_t> reversed(ids.rbegin(), ids.rend()), shuffled = ids;
    std::shuffle(shuffled.begin(), shuffled.end(), std::mt19937(7));

    const Solved reference = solve_with(sim, space, 1);
    std::size_t loaded = 0;
    for (const collide::SolverContact& c : reference.contacts) loaded += c.lambda_n > 0.0;
    ASSERT_GT(loaded, sim.particle_count()) << "a heap: more loaded contacts than balls";
    expect_same(reference, solve_with(sim, {}, 1), "no order (index order)");
    expect_same(reference, solve_with(sim, reversed, 1), "reversed");
    expect_same(reference, solve_with(sim, shuffled, 1), "shuffled");
    expect_same(reference, solve_with(sim, shuffled, 2), "shuffled, two threads");
}

}  // namespace
}  // namespace pl
