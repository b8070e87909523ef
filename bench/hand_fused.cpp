// Reference (b): the practical limit of this machine for the comparison workload. One
// hand-fused structure-of-arrays loop in double precision: gravity + quadratic drag,
// semi-implicit Euler, six walls clamped and reflected with selects (no branches), so GCC
// vectorises it (-fno-math-errno lets sqrt vectorise). All balls of the workload are identical,
// so the drag constant and the radius are hoisted out of the loop: nothing is read or written
// but the six state arrays. It keeps no ledger, no events, no resting contact; with
// Bookkeeping::drag_ledger (hand_fused.hpp) it also keeps the per-particle drag ledger, and so
// reads and writes a seventh array.
#include "hand_fused.hpp"

#include "physics/stepping/fast_kernel.hpp"
#include "physics/stepping/thread_pool.hpp"
#include "registry.hpp"
#include "workloads.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace pl::bench {

namespace {

// __restrict on the parameters (GCC ignores it on local pointers) tells the vectoriser the
// arrays do not overlap; -fopt-info-vec reports "loop vectorized using 64 byte vectors".
// Ledger: each particle's loss to drag also grows by mass * h * c |u|^2 (the drag power per unit
// mass, c |u|^2, over the step, as the engine's semi-implicit Euler step integrates it); without
// it drag_loss is not touched.
template <bool Ledger>
void fused_step(std::size_t n, double* __restrict x, double* __restrict y, double* __restrict z,
                double* __restrict vx, double* __restrict vy, double* __restrict vz, double* __restrict drag_loss,
                const FusedParams p) {
    const double h = p.h, k = p.k, e = p.restitution, m = p.mass;
    for (std::size_t i = 0; i < n; ++i) {
        double ux = vx[i], uy = vy[i], uz = vz[i];
        const double u2 = ux * ux + uy * uy + uz * uz;
        const double c = k * std::sqrt(u2);
        if constexpr (Ledger) drag_loss[i] = drag_loss[i] + m * (h * (c * u2));
        ux = ux + h * (p.gx - c * ux);
        uy = uy + h * (p.gy - c * uy);
        uz = uz + h * (p.gz - c * uz);
        const double px = x[i] + h * ux, py = y[i] + h * uy, pz = z[i] + h * uz;
        // Clamp into the room and reflect the normal velocity with restitution, as selects.
        const bool below_x = px < p.lo_x, above_x = px > p.hi_x;
        const bool below_y = py < p.lo_y, above_y = py > p.hi_y;
        const bool below_z = pz < p.lo_z, above_z = pz > p.hi_z;
        x[i] = below_x ? p.lo_x : (above_x ? p.hi_x : px);
        y[i] = below_y ? p.lo_y : (above_y ? p.hi_y : py);
        z[i] = below_z ? p.lo_z : (above_z ? p.hi_z : pz);
        vx[i] = (below_x | above_x) ? -e * ux : ux;
        vy[i] = (below_y | above_y) ? -e * uy : uy;
        vz[i] = (below_z | above_z) ? -e * uz : uz;
    }
}

void fused_step(SoaState& s, const FusedParams& p, std::size_t begin, std::size_t end) {
    auto* const step = s.drag_loss.empty() ? &fused_step<false> : &fused_step<true>;
    step(end - begin, s.x.data() + begin, s.y.data() + begin, s.z.data() + begin, s.vx.data() + begin,
         s.vy.data() + begin, s.vz.data() + begin, s.drag_loss.empty() ? nullptr : s.drag_loss.data() + begin, p);
}

// `steps` steps of particles [begin, end), blocked as the engine's Simulation::step_n is
// (fast_kernel.hpp, block_length): with several steps, each block takes all of them while it is
// in cache.
void fused_steps(SoaState& s, const FusedParams& p, std::size_t begin, std::size_t end, int steps) {
    const std::size_t block = steps == 1 ? end - begin : block_length(end - begin);
    for (std::size_t b = begin; b < end; b += block)
        for (int k = 0; k < steps; ++k) fused_step(s, p, b, std::min(end, b + block));
}

// With threads > 1: the same particle ranges on the same thread pool as the engine, so the
// two-thread speed-up of the limit shows what the machine allows at each size.
void fused_steps(SoaState& s, const FusedParams& p, int threads, int steps) {
    const std::size_t n = s.x.size();
    const std::size_t ranges = particle_ranges(n, threads);
    if (ranges <= 1) {
        fused_steps(s, p, 0, n, steps);
        return;
    }
    auto task = [&](std::size_t k) {
        fused_steps(s, p, range_begin(n, ranges, k), range_begin(n, ranges, k + 1), steps);
    };
    ThreadPool::shared().run(ranges, std::min<std::size_t>(ranges, static_cast<std::size_t>(threads)), task);
}

void run_limit(benchmark::State& state, Workload w, std::size_t n, int threads, int steps = 1) {
    FusedLimit limit(make_workload(w, n));
    int taken = 0;
    for (auto _ : state) {
        if (taken + steps > steps_per_window) {
            state.PauseTiming();
            limit.reload();
            taken = 0;
            state.ResumeTiming();
        }
        limit.step(threads, steps);
        taken += steps;
    }
    benchmark::DoNotOptimize(limit.positions());
    state.counters[rate_counter] = benchmark::Counter(
        static_cast<double>(state.iterations()) * static_cast<double>(steps) * static_cast<double>(n),
        benchmark::Counter::kIsRate);
}

}  // namespace

FusedLimit::FusedLimit(WorkloadScene scene, Bookkeeping bookkeeping)
    : scene_(std::move(scene)), bookkeeping_(bookkeeping) {
    const Model& m = scene_.model;
    const ParticleSpec& ball = scene_.particles.front();
    const double r = ball.radius;
    const Vec3 lo = m.room.min_corner(), hi = m.room.max_corner();
    params_ = {m.integrator.dt,
               workload_drag_constant(m, ball),
               m.contact.restitution,
               ball.mass,
               m.world.gravity.x,
               m.world.gravity.y,
               m.world.gravity.z,
               lo.x + r,
               lo.y + r,
               lo.z + r,
               hi.x - r,
               hi.y - r,
               hi.z - r};
    reload();
}

void FusedLimit::reload() {
    const std::size_t n = scene_.particles.size();
    for (auto* v : {&s_.x, &s_.y, &s_.z, &s_.vx, &s_.vy, &s_.vz}) v->resize(n);
    if (bookkeeping_ == Bookkeeping::drag_ledger) s_.drag_loss.assign(n, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
        const ParticleSpec& q = scene_.particles[i];
        s_.x[i] = q.position.x;
        s_.y[i] = q.position.y;
        s_.z[i] = q.position.z;
        s_.vx[i] = q.velocity.x;
        s_.vy[i] = q.velocity.y;
        s_.vz[i] = q.velocity.z;
    }
}

void FusedLimit::step(int threads, int steps) { fused_steps(s_, params_, threads, steps); }

void register_limit_benchmarks() {
    for (Workload w : {Workload::drag_walls, Workload::drag_open})
        for (std::size_t n : sizes)
            benchmark::RegisterBenchmark(
                (std::string("limit_hand_fused/") + to_string(w) + "/n:" + size_label(n)).c_str(),
                [w, n](benchmark::State& state) { run_limit(state, w, n, 1); })
                ->UseRealTime()
                ->Unit(benchmark::kMicrosecond);
    // 32 steps per call, blocked as the engine's step_n: the limit for engine_steps.
    for (std::size_t n : sizes)
        for (int threads : thread_settings()) {
            benchmark::RegisterBenchmark(
                ("limit_hand_fused/drag_walls/steps:32/n:" + size_label(n) + "/threads:" + std::to_string(threads))
                    .c_str(),
                [n, threads](benchmark::State& state) { run_limit(state, Workload::drag_walls, n, threads, 32); })
                ->UseRealTime()
                ->Unit(benchmark::kMicrosecond);
        }
    if (hardware_threads() < 2) return;
    for (std::size_t n : sizes) {
        const int threads = hardware_threads();
        benchmark::RegisterBenchmark(
            ("limit_hand_fused/drag_walls/n:" + size_label(n) + "/threads:" + std::to_string(threads)).c_str(),
            [n, threads](benchmark::State& state) { run_limit(state, Workload::drag_walls, n, threads); })
            ->UseRealTime()
            ->Unit(benchmark::kMicrosecond);
    }
}

}  // namespace pl::bench
