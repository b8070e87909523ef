// The engine and the hand-fused limit timed in turn within one benchmark, on one thread and on
// all of them: a window of steps of each, alternately, so that the rates, their ratio and the
// speed-ups come from the same moments of the machine. The development VM runs a core up to 25%
// slower for minutes at a time (RESULTS.md), which benchmarks run minutes apart cannot cancel;
// windows a few milliseconds apart mostly can.
#include "hand_fused.hpp"
#include "registry.hpp"
#include "workloads.hpp"

#include "physics/stepping/simulation.hpp"

#include <benchmark/benchmark.h>

#include <chrono>
#include <string>

namespace pl::bench {

namespace {

using Clock = std::chrono::steady_clock;

double seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

// One window of the engine (Simulation::step_n on `threads` threads) from the initial particles:
// its seconds. It starts with the state just written (constructed), as the limit's window does.
double engine_window(const WorkloadScene& scene, int threads, int calls, int steps) {
    Simulation sim(scene.model, scene.particles);
    sim.set_threads(threads);
    const auto t0 = Clock::now();
    for (int c = 0; c < calls; ++c) {
        sim.step_n(static_cast<std::uint64_t>(steps));
        benchmark::DoNotOptimize(sim.drain_events().data());
    }
    return seconds(Clock::now() - t0);
}

double limit_window(FusedLimit& limit, int threads, int calls, int steps) {
    limit.reload();
    const auto t0 = Clock::now();
    for (int c = 0; c < calls; ++c) limit.step(threads, steps);
    const double s = seconds(Clock::now() - t0);
    benchmark::DoNotOptimize(limit.positions());
    return s;
}

// One iteration: the engine on one thread through a window of steps_per_window steps from the
// initial particles and the limit through the same steps, `steps` per call for both, then the
// limit with the drag ledger (hand_fused.hpp, Bookkeeping) through them on one thread; with
// threads > 1 then the engine's and the limit's windows on `threads` threads. Each window starts
// with its state just written (the engine constructed, the limit reloaded), so none finds
// another's data in the caches. The order of each pair flips from one iteration to the next: the
// worker thread sleeps through the one-thread windows, and the first multi-threaded window of an
// iteration pays for waking it. Ratio counters are ratios of summed times, so every window weighs
// as it lasted.
void run_paired(benchmark::State& state, std::size_t n, int steps, int threads) {
    const WorkloadScene scene = make_workload(Workload::drag_walls, n);
    FusedLimit limit(scene), ledger_limit(scene, Bookkeeping::drag_ledger);
    const int calls = steps_per_window / steps;
    double engine_1 = 0.0, limit_1 = 0.0, ledger_1 = 0.0, engine_t = 0.0, limit_t = 0.0;
    bool engine_first = true;
    // Times the engine and the limit on `t` threads in this iteration's order; returns their sum.
    auto pair = [&](int t, double& engine, double& fused) {
        double e = 0.0, l = 0.0;
        if (engine_first) e = engine_window(scene, t, calls, steps);
        l = limit_window(limit, t, calls, steps);
        if (!engine_first) e = engine_window(scene, t, calls, steps);
        engine += e;
        fused += l;
        return e + l;
    };
    for (auto _ : state) {
        double seconds_in_windows = pair(1, engine_1, limit_1);
        const double ledger = limit_window(ledger_limit, 1, calls, steps);
        ledger_1 += ledger;
        seconds_in_windows += ledger;
        if (threads > 1) seconds_in_windows += pair(threads, engine_t, limit_t);
        state.SetIterationTime(seconds_in_windows);
        engine_first = !engine_first;
    }
    const double particle_steps =
        static_cast<double>(state.iterations()) * calls * steps * static_cast<double>(n);
    state.counters["engine_rate"] = particle_steps / engine_1;
    state.counters["limit_rate"] = particle_steps / limit_1;
    state.counters["engine/limit"] = limit_1 / engine_1;
    state.counters["ledger_limit/limit"] = limit_1 / ledger_1;
    if (threads > 1) {
        state.counters["engine_speedup"] = engine_1 / engine_t;
        state.counters["limit_speedup"] = limit_1 / limit_t;
    }
}

}  // namespace

std::string paired_name(int steps, std::size_t n, int threads) {
    return "paired/drag_walls/steps:" + std::to_string(steps) + "/n:" + size_label(n) + "/threads:" +
           std::to_string(threads);
}

void register_paired_benchmarks() {
    // One setting: the most threads (1 and that many are timed in turn), 1 on a one-core machine.
    const int threads = thread_settings().back();
    for (int steps : {1, 32})
        for (std::size_t n : sizes)
            benchmark::RegisterBenchmark(paired_name(steps, n, threads).c_str(),
                                         [n, steps, threads](benchmark::State& state) {
                                             run_paired(state, n, steps, threads);
                                         })
                ->UseManualTime()
                ->Unit(benchmark::kMillisecond);
}

}  // namespace pl::bench
