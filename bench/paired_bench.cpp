// The engine and the hand-fused limit timed in turn within one benchmark: a window of steps of
// each, alternately, so that both rates and their ratio come from the same moments of the
// machine. The development VM runs a core up to 25% slower for minutes at a time (RESULTS.md),
// which benchmarks run minutes apart cannot cancel; windows a few milliseconds apart can.
#include "hand_fused.hpp"
#include "registry.hpp"
#include "workloads.hpp"

#include "physics/simulation.hpp"

#include <benchmark/benchmark.h>

#include <chrono>
#include <string>

namespace pl::bench {

namespace {

using Clock = std::chrono::steady_clock;

double seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

// One iteration: the engine (Simulation::step_n, one thread) through a window of
// steps_per_window steps from the initial particles, then the limit through the same steps,
// `steps` per call for both. Each starts its window with its state just written (the engine
// constructed, the limit reloaded), so neither finds the other's data in the caches.
void run_paired(benchmark::State& state, std::size_t n, int steps) {
    const WorkloadScene scene = make_workload(Workload::drag_walls, n);
    FusedLimit limit(scene);
    const int calls = steps_per_window / steps;
    double engine_s = 0.0, limit_s = 0.0;
    for (auto _ : state) {
        Simulation sim(scene.model, scene.particles);
        sim.set_threads(1);
        const auto t0 = Clock::now();
        for (int c = 0; c < calls; ++c) {
            sim.step_n(static_cast<std::uint64_t>(steps));
            benchmark::DoNotOptimize(sim.drain_events().data());
        }
        const auto t1 = Clock::now();
        limit.reload();
        const auto t2 = Clock::now();
        for (int c = 0; c < calls; ++c) limit.step(1, steps);
        const auto t3 = Clock::now();
        benchmark::DoNotOptimize(limit.positions());
        const double engine = seconds(t1 - t0), fused = seconds(t3 - t2);
        engine_s += engine;
        limit_s += fused;
        state.SetIterationTime(engine + fused);
    }
    const double particle_steps =
        static_cast<double>(state.iterations()) * calls * steps * static_cast<double>(n);
    state.counters["engine_rate"] = particle_steps / engine_s;
    state.counters["limit_rate"] = particle_steps / limit_s;
    state.counters["engine/limit"] = limit_s / engine_s;
}

}  // namespace

void register_paired_benchmarks() {
    for (int steps : {1, 32})
        for (std::size_t n : sizes)
            benchmark::RegisterBenchmark(
                ("paired/drag_walls/steps:" + std::to_string(steps) + "/n:" + size_label(n) + "/threads:1").c_str(),
                [n, steps](benchmark::State& state) { run_paired(state, n, steps); })
                ->UseManualTime()
                ->Unit(benchmark::kMillisecond);
}

}  // namespace pl::bench
