#include "physics/stepping/fast_kernel.hpp"

#include "physics/model/terms/term_list.hpp"
#include "physics/stepping/range_stepper.hpp"
#include "physics/stepping/thread_pool.hpp"

#include <algorithm>
#include <vector>

namespace pl {

namespace {

using namespace fast;

// Adds a range's counters and warnings to the kernel's (events are already in place).
void merge(const KernelContext& k, const RangeOutput& out) {
    k.counters += out.counters;
    for (const Warning& w : out.frozen) k.warnings.raise(w.kind, w.particle, w.t, w.value);
}

template <Flight M, class F>
void fast_step_kernel(const KernelContext& k, std::uint32_t steps) {
    const std::size_t n = k.state.size();
    const std::size_t ranges = particle_ranges(n, k.threads);
    if (ranges <= 1 && steps == 1) {
        RangeOutput out;
        out.events = k.events.events;
        RangeStepper<M, F>(k, &out, 1).run(0, n);
        merge(k, out);
        k.end_step();
        return;
    }
    // One output per range and step (range r's steps at r * steps). Kept from call to call (one
    // set per calling thread), so that the event vectors keep their room instead of being
    // allocated, grown and freed every call. The tasks reach it through `outs`: named inside a
    // task, `kept` would be the worker's own, empty copy.
    static thread_local std::vector<RangeOutput> kept;
    std::vector<RangeOutput>& outs = kept;
    outs.resize(ranges * steps);
    for (RangeOutput& out : outs) {
        out.events = &out.own_events;
        out.own_events.clear();
        out.frozen.clear();
        out.counters = {};
    }
    auto task = [&](std::size_t r) {
        RangeStepper<M, F>(k, &outs[r * steps], steps)
            .run(range_begin(n, ranges, r), range_begin(n, ranges, r + 1));
    };
    if (ranges == 1) task(0);
    else ThreadPool::shared().run(ranges, std::min(ranges, thread_count(k.threads)), task);
    // Step by step, range by range: the order one step at a time gives.
    std::vector<Event>& sink = *k.events.events;
    for (std::uint32_t step = 0; step < steps; ++step) {
        for (std::size_t r = 0; r < ranges; ++r) {
            const RangeOutput& out = outs[r * steps + step];
            sink.insert(sink.end(), out.own_events.begin(), out.own_events.end());
            merge(k, out);
        }
        k.end_step();
    }
}

// The kernel of method M for the terms the model enables.
template <Flight M>
StepKernel pick_forces(const Model& m) {
    return terms::with_enabled_terms<terms::FlightTermGroups>(
        m, []<class F>() -> StepKernel { return &fast_step_kernel<M, F>; });
}

}  // namespace

bool has_fast_flight(const Model& m) {
    switch (m.integrator.method) {
        case Method::explicit_euler:
        case Method::semi_implicit_euler:
        case Method::velocity_verlet:
        case Method::rk4: return true;
        case Method::dopri5:
        case Method::exponential: return false;
    }
    return false;
}

StepKernel pick_fast_kernel(const Model& m) {
    switch (m.integrator.method) {
        case Method::explicit_euler: return pick_forces<Flight::explicit_euler>(m);
        case Method::semi_implicit_euler: return pick_forces<Flight::semi_implicit_euler>(m);
        case Method::velocity_verlet: return pick_forces<Flight::velocity_verlet>(m);
        case Method::rk4: return pick_forces<Flight::rk4>(m);
        case Method::dopri5:
        case Method::exponential: return pick_forces<Flight::none>(m);
    }
    return pick_forces<Flight::none>(m);
}

std::size_t block_length(std::size_t n) {
    const std::size_t blocks = std::max<std::size_t>(1, (n + block_particles / 2) / block_particles);
    return (n / blocks + fast_chunk - 1) / fast_chunk * fast_chunk;
}

// Boundaries on multiples of 64 particles keep the threads' stores off each other's cache lines.
std::size_t range_begin(std::size_t n, std::size_t ranges, std::size_t k) {
    if (k >= ranges) return n;
    return (n * k / ranges) & ~std::size_t{63};
}

std::size_t thread_count(int threads) { return static_cast<std::size_t>(threads > 0 ? threads : hardware_threads()); }

std::size_t particle_ranges(std::size_t n, int threads) {
    const std::size_t t = thread_count(threads);
    if (t <= 1) return 1;
    return std::max<std::size_t>(1, std::min(t * ranges_per_thread, n / min_particles_per_range));
}

}  // namespace pl
