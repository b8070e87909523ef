// Threads split the particles into contiguous ranges; each range's events are appended in range
// order. So state, ledger, events, warnings and counters must be bit-identical for any thread count.
#include "physics/model/emitter.hpp"
#include "physics/stepping/fast_kernel.hpp"
#include "physics/stepping/simulation.hpp"
#include "physics/stepping/thread_pool.hpp"
#include "same_state.hpp"
#include "test_scenes.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cstdint>
#include <thread>
#include <vector>

namespace pl {
namespace {

using test::crowd;
using test::Crowd;

void expect_same_for_1_2_3_threads(const Crowd& c, int steps) {
    std::vector<Simulation> runs;
    for (int threads : {1, 2, 3}) {
        runs.emplace_back(c.model, c.particles);
        runs.back().set_threads(threads);
        runs.back().step_n(static_cast<std::uint64_t>(steps));
    }
    EXPECT_GT(runs[0].events().size(), 100u);
    // Warnings are raised in particle order after the monitor's threaded scan.
    if (c.model.drag.model != DragModel::none) {
        EXPECT_GT(runs[0].warnings().size(), 0u);
    }
    for (std::size_t k = 1; k < runs.size(); ++k) {
        SCOPED_TRACE("threads " + std::to_string(k + 1));
        test::expect_identical(runs[k], runs[0]);
        EXPECT_EQ(runs[k].counters().fast_path, runs[0].counters().fast_path);
    }
}

TEST(Threading, StatesAndEventsIdenticalFor1And2And3ThreadsWithDragAndWind) {
    const Crowd c = crowd(3600, Method::semi_implicit_euler, DragModel::quadratic, WindKind::shear);
    // Different splits: 1, 2 and 3 particle ranges.
    ASSERT_EQ(particle_ranges(c.particles.size(), 2), 2 * ranges_per_thread);
    ASSERT_EQ(particle_ranges(c.particles.size(), 3), 3 * ranges_per_thread);
    expect_same_for_1_2_3_threads(c, 80);
}

TEST(Threading, StatesAndEventsIdenticalWithoutWindOnTheVectorisedPath) {
    expect_same_for_1_2_3_threads(crowd(3600, Method::rk4, DragModel::linear, WindKind::none), 80);
}

TEST(Threading, StatesAndEventsIdenticalForTheAdaptiveMethod) {
    expect_same_for_1_2_3_threads(crowd(3600, Method::dopri5, DragModel::quadratic, WindKind::none), 15);
}

TEST(Threading, ThreadedFastKernelMatchesTheGenericKernel) {
    const Crowd c = crowd(3000, Method::semi_implicit_euler, DragModel::quadratic, WindKind::gust);
    Simulation threaded(c.model, c.particles), generic(c.model, c.particles);
    threaded.set_threads(2);
    generic.set_kernel(KernelChoice::generic);
    threaded.step_n(80);
    generic.step_n(80);
    test::expect_identical(threaded, generic);
}

TEST(Threading, SmallScenesStaySingleThreaded) {
    EXPECT_EQ(particle_ranges(100, 8), 1u);
    EXPECT_EQ(particle_ranges(2 * min_particles_per_range - 1, 8), 1u);
    EXPECT_EQ(particle_ranges(2 * min_particles_per_range, 8), 2u);
    EXPECT_EQ(particle_ranges(1000000, 1), 1u);
    EXPECT_EQ(particle_ranges(1000000, 3), 3 * ranges_per_thread);
    EXPECT_EQ(thread_count(0), static_cast<std::size_t>(hardware_threads()));
    EXPECT_EQ(thread_count(5), 5u);
}

// Range borders fall on multiples of 64 particles and the state arrays start on cache lines, so
// no cache line is written by two threads (and the kernels' 64-byte vector loads do not straddle
// two lines).
TEST(Threading, RangesDoNotShareCacheLines) {
    const Crowd c = crowd(10000, Method::semi_implicit_euler, DragModel::quadratic, WindKind::none);
    const Simulation sim(c.model, c.particles);
    const ParticleState& s = sim.state();
    auto on_line = [](const void* p) { return reinterpret_cast<std::uintptr_t>(p) % 64 == 0; };
    for (const auto* a : {&s.x, &s.y, &s.z, &s.vx, &s.vy, &s.vz, &s.dissipated_drag, &s.dissipated_bounce,
                          &s.dissipated_friction, &s.wind_work})
        EXPECT_TRUE(on_line(a->data()));
    EXPECT_TRUE(on_line(s.resting.data()));
    EXPECT_TRUE(on_line(s.frozen.data()));
    const std::size_t n = s.size(), ranges = particle_ranges(n, 3);
    for (std::size_t k = 1; k < ranges; ++k) EXPECT_EQ(range_begin(n, ranges, k) % 64, 0u);
}

TEST(Threading, PoolRunsEveryTaskExactlyOnce) {
    ThreadPool pool;
    for (std::size_t threads : {1u, 2u, 3u, 5u}) {
        for (std::size_t tasks : {1u, 2u, 7u, 100u}) {
            std::vector<std::atomic<int>> runs(tasks);
            auto task = [&](std::size_t k) { runs[k].fetch_add(1); };
            for (int round = 0; round < 20; ++round) pool.run(tasks, threads, task);
            for (std::size_t k = 0; k < tasks; ++k) EXPECT_EQ(runs[k].load(), 20) << threads << " threads, task " << k;
        }
    }
    EXPECT_EQ(pool.worker_count(), 4u);
}

TEST(Threading, ConcurrentCallersOfTheSharedPoolEachGetTheirWorkDone) {
    // A second caller finds the pool busy and runs its tasks itself: never a deadlock.
    auto caller = [](std::atomic<long>& sum) {
        for (int round = 0; round < 200; ++round) {
            auto task = [&](std::size_t k) { sum.fetch_add(static_cast<long>(k) + 1); };
            ThreadPool::shared().run(4, 2, task);
        }
    };
    std::atomic<long> a{0}, b{0};
    std::thread other(caller, std::ref(b));
    caller(a);
    other.join();
    EXPECT_EQ(a.load(), 200 * 10);
    EXPECT_EQ(b.load(), 200 * 10);
}

}  // namespace
}  // namespace pl
