// Simulation::step_n lets the fast kernel take several steps per call, block of particles by
// block of particles (fast_kernel.hpp, block_particles). Whatever the grouping, the result must
// be bit for bit that of one step at a time: state, ledger, events in the same order with the
// same times, warnings (frozen particles and the monitor's), counters.
#include "physics/stepping/fast_kernel.hpp"
#include "physics/stepping/simulation.hpp"
#include "same_state.hpp"
#include "test_scenes.hpp"

#include <gtest/gtest.h>

#include <string>

namespace pl {
namespace {

using test::Crowd;

// More particles than one block, in a small room with a gusting wind (so that each step's time
// matters), two of them bound to become non-finite and freeze, one too fast for the drag model
// (a Mach warning; the slow ones get Reynolds-range warnings).
Crowd gusty_crowd(std::size_t n, Method method) {
    Crowd c = test::crowd(n, method, DragModel::quadratic, WindKind::gust, 7);
    c.particles[n / 3].velocity = {1e200, -1e200, 0.0};  // |v|^2 overflows: frozen in the first step
    c.particles[n - 5].velocity = {0.0, 1e300, 0.0};
    c.particles[n / 2].velocity = {150.0, 0.0, 0.0};  // above Mach 0.3: a warning
    return c;
}

void expect_same_as_one_step_at_a_time(const Crowd& c, std::uint64_t steps, int threads) {
    Simulation grouped(c.model, c.particles), single(c.model, c.particles);
    grouped.set_threads(threads);
    single.set_threads(1);
    grouped.step_n(steps);
    for (std::uint64_t k = 0; k < steps; ++k) single.step();
    EXPECT_EQ(grouped.step_count(), steps);
    EXPECT_GT(test::of_kind(single.events(), EventKind::bounce).size(), 100u);
    EXPECT_EQ(test::of_kind(single.events(), EventKind::frozen).size(), 2u);
    EXPECT_GE(single.warnings().size(), 3u);  // two frozen particles and the fast one
    test::expect_identical(grouped, single);
    EXPECT_EQ(grouped.counters().fast_path, single.counters().fast_path);
}

TEST(StepBlocks, ManyStepsPerCallGiveTheBitsOfOneStepAtATime) {
    // Two blocks in one range on one thread, a block per range on two; the steps cross the
    // monitor's samples.
    const Crowd c = gusty_crowd(2 * block_particles + 1000, Method::semi_implicit_euler);
    for (int threads : {1, 2}) {
        SCOPED_TRACE("threads " + std::to_string(threads));
        expect_same_as_one_step_at_a_time(c, 70, threads);
    }
}

TEST(StepBlocks, EveryFlightMethodAndTheScalarPathsGroupTheSameWay) {
    for (Method method : {Method::explicit_euler, Method::velocity_verlet, Method::rk4, Method::dopri5,
                          Method::exponential}) {
        SCOPED_TRACE(to_string(method));
        expect_same_as_one_step_at_a_time(gusty_crowd(600, method), 40, 1);
    }
}

TEST(StepBlocks, StepNStopsAtEachStepTheMonitorSamples) {
    // Steps taken in uneven pieces: the monitor must see the same states.
    const Crowd c = gusty_crowd(3000, Method::semi_implicit_euler);
    Simulation pieces(c.model, c.particles), single(c.model, c.particles);
    for (std::uint64_t n : {5u, 40u, 1u, 31u, 64u, 3u}) pieces.step_n(n);
    for (int k = 0; k < 144; ++k) single.step();
    test::expect_identical(pieces, single);
}

}  // namespace
}  // namespace pl
