// Collision costs that are ratios, timed in turn within one benchmark (as paired_bench.cpp does
// for the engine and its limit): two simulations of a scene advance together, a window of steps
// of one, then the same steps of the other, the order flipped from one window to the next, so
// that both sides of a ratio are measured at the same moments of the machine. The development
// VM's memory-bound runs vary by up to 1.5x from run to run, far more than the 1.6x thread
// scaling or the 2x growth they are meant to show; windows a few milliseconds apart mostly
// cancel that.
//  - Thread scaling: the same scene from the same state on one thread and on two. The two
//    simulations are bit-identical step for step (the collision pass's threads change no bit),
//    so both windows do exactly the same work; the benchmark checks that they end in the same
//    state and fails if not.
//  - Growth: the settling pile of 1e3 and a larger one on one thread, the same steps from the
//    same time (0.7 s, heaped and still settling), cost per particle-step compared.
#include "collision_scenes.hpp"
#include "registry.hpp"

#include "physics/stepping/simulation.hpp"

#include <benchmark/benchmark.h>

#include <chrono>
#include <memory>
#include <string>
#include <utility>

namespace pl::bench {

namespace {

using Clock = std::chrono::steady_clock;

// The scene advanced to `from` (on two threads: the threads change no bit), then set to `threads`.
std::unique_ptr<Simulation> started(const CollisionScene& scene, double from, int threads) {
    auto sim = std::make_unique<Simulation>(scene.model, scene.particles);
    sim->set_threads(2);
    if (from > 0.0) sim->run_until(from);
    else sim->step_n(10);  // the collision pass's buffers reach their size
    sim->set_threads(threads);
    return sim;
}

double window(Simulation& sim, int steps) {
    const auto t0 = Clock::now();
    sim.step_n(static_cast<std::uint64_t>(steps));
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

// Windows of `steps` steps of a and of b in turn, the order flipped each iteration; the seconds of
// each summed into seconds_a and seconds_b.
void in_turn(benchmark::State& state, Simulation& a, Simulation& b, int steps, double& seconds_a, double& seconds_b) {
    bool a_first = true;
    for (auto _ : state) {
        const double first = window(a_first ? a : b, steps);
        const double second = window(a_first ? b : a, steps);
        seconds_a += a_first ? first : second;
        seconds_b += a_first ? second : first;
        state.SetIterationTime(first + second);
        a_first = !a_first;
    }
}

bool same_state(const Simulation& a, const Simulation& b) {
    const ParticleState &s = a.state(), &t = b.state();
    for (std::size_t i = 0; i < s.size(); ++i)
        if (s.position(i) != t.position(i) || s.velocity(i) != t.velocity(i) || s.spin(i) != t.spin(i)) return false;
    return a.step_count() == b.step_count();
}

// One thread against two on the same scene from time `from` (0: from the start, after 10 steps).
void run_scaling(benchmark::State& state, const CollisionScene& scene, double from, int steps) {
    const auto one = started(scene, from, 1), two = started(scene, from, 2);
    double seconds_1 = 0.0, seconds_2 = 0.0;
    in_turn(state, *one, *two, steps, seconds_1, seconds_2);
    if (!same_state(*one, *two)) return state.SkipWithError("one and two threads ended in different states");
    const double particle_steps =
        static_cast<double>(state.iterations()) * steps * static_cast<double>(scene.particles.size());
    state.counters["rate_1"] = particle_steps / seconds_1;
    state.counters["rate_2"] = particle_steps / seconds_2;
    state.counters["speedup"] = seconds_1 / seconds_2;
    const double simulated = static_cast<double>(state.iterations()) * steps * scene.model.integrator.dt;
    state.counters["real-time factor_2"] = simulated / seconds_2;  // the GUI's physics thread: 1 or more
}

// The settling pile of 1e3 against one of n balls, one thread each, the same steps from 0.7 s.
void run_growth(benchmark::State& state, std::size_t n, int steps) {
    const std::size_t small = 1000;
    const auto few = started(pile(small), 0.7, 1), many = started(pile(n), 0.7, 1);
    double seconds_few = 0.0, seconds_many = 0.0;
    in_turn(state, *few, *many, steps, seconds_few, seconds_many);
    const double windows = static_cast<double>(state.iterations()) * steps;
    const double per_few = seconds_few / (windows * static_cast<double>(small));
    const double per_many = seconds_many / (windows * static_cast<double>(n));
    state.counters["ns/particle-step_1e3"] = 1e9 * per_few;
    state.counters["ns/particle-step_n"] = 1e9 * per_many;
    state.counters["growth"] = per_many / per_few;
}

}  // namespace

void register_collision_paired_benchmarks() {
    // Few iterations of short windows: each of a pile's windows lasts 0.1 s (1e4) to 1 s (1e5).
    for (const std::size_t n : {std::size_t{10000}, std::size_t{100000}})
        benchmark::RegisterBenchmark(("collisions/paired/pile/settling/threads:1-2/n:" + std::to_string(n)).c_str(),
                                     [n](benchmark::State& s) { run_scaling(s, pile(n), 0.7, n >= 100000 ? 2 : 5); })
            ->UseManualTime()
            ->Iterations(n >= 100000 ? 6 : 20)
            ->Unit(benchmark::kMillisecond);
    // The gas at dt = 1 ms, and at 1e5 with the GUI's dt of 2 ms: windows of 42 or 30 steps hold
    // six or five of the pair cache's grid runs, the same ones on both sides (the two simulations
    // are the same step for step).
    for (const auto& [n, dt] : {std::pair{std::size_t{10000}, 1e-3}, std::pair{std::size_t{100000}, 1e-3},
                                std::pair{std::size_t{100000}, 2e-3}})
        benchmark::RegisterBenchmark(("collisions/paired/gas/" + std::string(dt > 1e-3 ? "dt:2ms/" : "") +
                                      "threads:1-2/n:" + std::to_string(n))
                                         .c_str(),
                                     [n, dt](benchmark::State& s) {
                                         run_scaling(s, dilute_gas(n, true, dt), 0.0, dt > 1e-3 ? 30 : 42);
                                     })
            ->UseManualTime()
            ->Iterations(n >= 100000 ? 20 : 100)
            ->Unit(benchmark::kMillisecond);
    for (const std::size_t n : {std::size_t{10000}, std::size_t{100000}})
        benchmark::RegisterBenchmark(("collisions/paired/pile/settling/growth/n:1000-" + std::to_string(n)).c_str(),
                                     [n](benchmark::State& s) { run_growth(s, n, n >= 100000 ? 2 : 5); })
            ->UseManualTime()
            ->Iterations(n >= 100000 ? 6 : 20)
            ->Unit(benchmark::kMillisecond);
}

}  // namespace pl::bench
