// Engine throughput: Simulation::step() as the GUI and CLI call it (the stepping kernel, then
// the event cap and the monitor: NaN guard, drag validity and stability checks), the stepping
// kernel alone (fast_kernel.hpp), and the step with the generic reference kernel, to show
// where the time goes. Every timed step is followed by drain_events(), as the callers do.
#include "physics/stepping/simulation.hpp"
#include "registry.hpp"
#include "workloads.hpp"

#include <benchmark/benchmark.h>

#include <string>
#include <vector>

namespace pl::bench {

namespace {

enum class Timed {
    step,         // Simulation::step()
    kernel_only,  // the kernel Simulation::step() calls, without the bookkeeping after it
    generic_step  // Simulation::step() with the generic reference kernel
};

// steps: steps per timed call (Simulation::step_n), as a GUI frame or a CLI output interval
// takes them; 1 is Simulation::step().
void run_engine(benchmark::State& state, const WorkloadScene& scene, int threads, Timed timed, int steps = 1) {
    const bool kernel_only = timed == Timed::kernel_only;
    auto fresh = [&] {
        Simulation sim(scene.model, scene.particles);
        sim.set_threads(threads);
        if (timed == Timed::generic_step) sim.set_kernel(KernelChoice::generic);
        for (int k = 0; k < scene.settle_steps; ++k) {
            sim.step();
            sim.drain_events();
        }
        return sim;
    };
    Simulation sim = fresh();
    int taken = 0;
    for (auto _ : state) {
        if (taken + steps > steps_per_window) {
            state.PauseTiming();
            sim = fresh();
            taken = 0;
            state.ResumeTiming();
        }
        if (kernel_only) sim.run_kernel(static_cast<std::uint32_t>(steps));
        else sim.step_n(static_cast<std::uint64_t>(steps));
        // Consumers take the events after every frame or output sample; left to pile up for a
        // whole window they would be a growing vector, reallocated and page-faulted, not
        // what any caller sees.
        benchmark::DoNotOptimize(sim.drain_events().data());
        taken += steps;
    }
    benchmark::DoNotOptimize(sim.state().x.data());
    state.counters[rate_counter] = benchmark::Counter(
        static_cast<double>(state.iterations()) * static_cast<double>(steps) * static_cast<double>(scene.particles.size()),
        benchmark::Counter::kIsRate);
}

void register_engine(Workload w, std::size_t n, int threads, Method method, const std::string& name,
                     Timed timed = Timed::step, int steps = 1) {
    benchmark::RegisterBenchmark(name.c_str(), [w, n, threads, method, timed, steps](benchmark::State& state) {
        const WorkloadScene scene = make_workload(w, n, method);
        run_engine(state, scene, threads, timed, steps);
    })->UseRealTime()->Unit(benchmark::kMicrosecond);
}


}  // namespace

void register_engine_benchmarks() {
    for (Workload w : {Workload::gravity, Workload::drag_walls, Workload::drag_walls_shear, Workload::drag_rest})
        for (std::size_t n : sizes)
            for (int threads : thread_settings())
                register_engine(w, n, threads, Method::semi_implicit_euler,
                                std::string("engine/") + to_string(w) + "/n:" + size_label(n) +
                                    "/threads:" + std::to_string(threads));
    for (std::size_t n : sizes)
        for (int threads : thread_settings())
            register_engine(Workload::drag_walls, n, threads, Method::semi_implicit_euler,
                            "kernel/drag_walls/n:" + size_label(n) + "/threads:" + std::to_string(threads),
                            Timed::kernel_only);
    // Several steps per call: each block of particles takes them all while it is in cache.
    for (int steps : {8, 32})
        for (std::size_t n : sizes)
            for (int threads : thread_settings())
                register_engine(Workload::drag_walls, n, threads, Method::semi_implicit_euler,
                                "engine_steps/drag_walls/steps:" + std::to_string(steps) + "/n:" + size_label(n) +
                                    "/threads:" + std::to_string(threads),
                                Timed::step, steps);
    for (std::size_t n : sizes)
        register_engine(Workload::drag_walls, n, 1, Method::semi_implicit_euler,
                        "engine_generic_kernel/drag_walls/n:" + size_label(n), Timed::generic_step);
    // Flight alone: the kernel where no wall is reached, against the limit in the same room.
    for (std::size_t n : sizes)
        register_engine(Workload::drag_open, n, 1, Method::semi_implicit_euler,
                        "kernel/drag_open/n:" + size_label(n) + "/threads:1", Timed::kernel_only);
}

void register_method_benchmarks() {
    for (Method m : {Method::explicit_euler, Method::semi_implicit_euler, Method::velocity_verlet, Method::rk4,
                     Method::dopri5, Method::exponential}) {
        const std::string base = std::string("method/") + to_string(m) + "/n:";
        register_engine(Workload::drag_walls, 1, 1, m, base + "1/threads:1");
        for (std::size_t n : sizes)
            for (int threads : thread_settings())
                register_engine(Workload::drag_walls, n, threads, m,
                                base + size_label(n) + "/threads:" + std::to_string(threads));
    }
}

}  // namespace pl::bench
