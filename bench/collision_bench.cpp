// What particle-particle collisions cost: a dilute gas (radius 5 mm, 1e3 to 1e5 particles at the
// density of 1e4 in a 2 m box, no gravity or drag, frictionless elastic walls) stepped with
// collisions on and off (and at 1e5 with the GUI's dt of 2 ms: its real-time target),
// the naive all-pairs test of the same swept boxes (O(n^2), up to where it is bearable), and a
// pile (balls of 2 cm dropped on a floor sized for about ten layers) while it settles, awake,
// and once it sleeps; on one and two threads; and the gas and the settling pile in Bullet (the
// peer, peers/bullet_peer.hpp).
#include "physics/collide/broad_phase.hpp"
#include "physics/collide/collision_pass.hpp"
#ifdef PL_HAS_BULLET
#include "peers/bullet_peer.hpp"
#endif
#include "physics/stepping/simulation.hpp"
#include "collision_scenes.hpp"
#include "registry.hpp"

#include <benchmark/benchmark.h>

#include <cmath>
#include <string>
#include <utility>

namespace pl::bench {

namespace {

// The pair cache's work, per step since the start: grid runs and mends, the largest margin and
// the grid's cell and entries per box at its last run.
void count_cache_work(benchmark::State& state, const Simulation& sim) {
    const collide::CollisionPass* pass = sim.collision_pass();
    if (!pass || pass->pair_cache().calls() == 0) return;
    const collide::PairCache& cache = pass->pair_cache();
    const auto calls = static_cast<double>(cache.calls());
    state.counters["grid runs/step"] = static_cast<double>(cache.grid_runs()) / calls;
    state.counters["mends/step"] = static_cast<double>(cache.mends()) / calls;
    state.counters["margin"] = cache.margin();
    state.counters["cell"] = cache.grid().cell_size();
    state.counters["entries/box"] =
        static_cast<double>(cache.grid().entry_count()) / static_cast<double>(sim.particle_count());
}

void run_gas(benchmark::State& state, std::size_t n, bool collisions, int threads = 1, double dt = 1e-3) {
    const CollisionScene g = dilute_gas(n, collisions, dt);
    Simulation sim(g.model, g.particles);
    sim.set_threads(threads);
    sim.step_n(10);  // the collision pass's buffers reach their size
    for (auto _ : state) sim.step();
    state.counters[rate_counter] =
        benchmark::Counter(static_cast<double>(n) * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
    state.counters["collisions/step"] = static_cast<double>(sim.collisions_total()) / static_cast<double>(sim.step_count());
    count_cache_work(state, sim);
    // Simulated seconds per wall second: the GUI's physics thread keeps real time at 1 or more.
    state.counters["real-time factor"] =
        benchmark::Counter(dt * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

// The broad phase against the all-pairs loop on the gas's boxes (one step's motion).
void run_pairs(benchmark::State& state, std::size_t n, bool grid) {
    const CollisionScene g = dilute_gas(n, true);
    collide::SweptBoxes boxes;
    boxes.resize(n);
    for (std::uint32_t i = 0; i < n; ++i) {
        const ParticleSpec& p = g.particles[i];
        for (int k = 0; k < 3; ++k) {
            const double end = p.position[k] + g.model.integrator.dt * p.velocity[k];
            boxes.box[i].lo[k] = std::min(p.position[k], end) - p.radius;
            boxes.box[i].hi[k] = std::max(p.position[k], end) + p.radius;
        }
        boxes.ids.push_back(i);
    }
    collide::BroadPhase broad;
    std::vector<collide::Pair> pairs;
    for (auto _ : state) {
        if (grid) broad.find_pairs(boxes, pairs);
        else collide::all_pairs(boxes, pairs);
        benchmark::DoNotOptimize(pairs.data());
    }
    state.counters[rate_counter] =
        benchmark::Counter(static_cast<double>(n) * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

#ifdef PL_HAS_BULLET
// The same gas stepped by Bullet (peers/bullet_peer.hpp): same particles, room, dt, e and mu.
PeerScene peer_scene(const CollisionScene& g) {
    PeerScene scene;
    scene.room = g.model.room;
    scene.gravity = g.model.world.gravity;
    scene.dt = g.model.integrator.dt;
    scene.restitution = g.model.collisions.restitution;
    scene.friction = g.model.collisions.friction;
    scene.particles = g.particles;
    return scene;
}

void run_bullet_gas(benchmark::State& state, std::size_t n) {
    BulletPeer peer(peer_scene(dilute_gas(n, true)));
    peer.step(10);
    for (auto _ : state) peer.step(1);
    state.counters[rate_counter] =
        benchmark::Counter(static_cast<double>(n) * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
    state.counters["contacts"] = static_cast<double>(peer.contacts());
}
#endif

// Steps of the pile from time `from` on (0.7 s: fallen and heaped, awake; 3 s: asleep).
void run_pile(benchmark::State& state, std::size_t n, double from, int threads = 1) {
    const CollisionScene g = pile(n);
    Simulation sim(g.model, g.particles);
    sim.set_threads(threads);
    sim.run_until(from);
    for (auto _ : state) sim.step();
    state.counters[rate_counter] =
        benchmark::Counter(static_cast<double>(n) * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
    state.counters["asleep"] = static_cast<double>(sim.asleep_count()) / static_cast<double>(n);
    state.counters["contacts"] = static_cast<double>(sim.resting_contacts()) / static_cast<double>(n);
    count_cache_work(state, sim);
}

#ifdef PL_HAS_BULLET
// The same pile stepped by Bullet from the same time on (Bullet deactivates still bodies, as
// particle-lab's islands sleep).
void run_bullet_pile(benchmark::State& state, std::size_t n, double from) {
    const CollisionScene g = pile(n);
    BulletPeer peer(peer_scene(g));
    peer.step(static_cast<int>(std::lround(from / g.model.integrator.dt)));
    for (auto _ : state) peer.step(1);
    state.counters[rate_counter] =
        benchmark::Counter(static_cast<double>(n) * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
    state.counters["contacts"] = static_cast<double>(peer.contacts()) / static_cast<double>(n);
}

// The pile `g` as particle-lab has it at time `from`: positions, velocities and spins.
std::vector<ParticleSpec> pile_at(const CollisionScene& g, double from) {
    Simulation sim(g.model, g.particles);
    sim.run_until(from);
    std::vector<ParticleSpec> heaped = g.particles;
    const ParticleState& s = sim.state();
    for (std::size_t i = 0; i < heaped.size(); ++i) {
        heaped[i].position = s.position(i);
        heaped[i].velocity = s.velocity(i);
        heaped[i].spin = s.spin(i);
    }
    return heaped;
}

// Bullet stepping the settling pile from particle-lab's state at `from` instead of its own (the
// pile of 1e5 would take Bullet over half an hour to settle): the same balls in the same places,
// still settling. Two untimed steps first, so that its contact caches hold the pile. A lower
// bound on Bullet's cost: its soft contacts let the pile sink closer, and it grows costlier as
// it does (at 1e4: 1.83 contacts a ball and 155 ms a step after 2 steps, 2.44 and 212 ms after
// 100; from its own fall, 2.67 and 316 ms).
void run_bullet_pile_from_ours(benchmark::State& state, std::size_t n, double from) {
    CollisionScene g = pile(n);
    g.particles = pile_at(g, from);
    BulletPeer peer(peer_scene(g));
    peer.step(2);
    for (auto _ : state) peer.step(1);
    state.counters[rate_counter] =
        benchmark::Counter(static_cast<double>(n) * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
    state.counters["contacts"] = static_cast<double>(peer.contacts()) / static_cast<double>(n);
}
#endif

}  // namespace

void register_collision_benchmarks() {
    // Piles of 1e5 take minutes to settle before the first timed step (in both engines): run them
    // by name, e.g. --benchmark_filter=pile.*n:100000.
#ifdef PL_HAS_BULLET
    for (const std::size_t n : {std::size_t{1000}, std::size_t{10000}, std::size_t{100000}})
        benchmark::RegisterBenchmark(("collisions/peer/bullet/gas/n:" + std::to_string(n)).c_str(),
                                     [n](benchmark::State& s) { run_bullet_gas(s, n); })
            ->UseRealTime();
    // Bullet's pile of 1e5 does not settle itself (at seconds a step that would take over half
    // an hour): it starts from particle-lab's pile at 0.7 s, and so does a pile of 1e4, beside
    // Bullet's own, to show what that start leaves out.
    for (const std::size_t n : {std::size_t{1000}, std::size_t{10000}})
        benchmark::RegisterBenchmark(("collisions/peer/bullet/pile/settling/n:" + std::to_string(n)).c_str(),
                                     [n](benchmark::State& s) { run_bullet_pile(s, n, 0.7); })
            ->UseRealTime()
            ->Iterations(20);
    for (const std::size_t n : {std::size_t{10000}, std::size_t{100000}})
        benchmark::RegisterBenchmark(("collisions/peer/bullet/pile/settling/from_ours/n:" + std::to_string(n)).c_str(),
                                     [n](benchmark::State& s) { run_bullet_pile_from_ours(s, n, 0.7); })
            ->UseRealTime()
            ->Iterations(n >= 100000 ? 3 : 20);
#endif
    for (const std::size_t n : {std::size_t{1000}, std::size_t{10000}, std::size_t{100000}}) {
        const auto iterations = static_cast<benchmark::IterationCount>(n >= 100000 ? 5 : 20);
        for (const auto& [phase, from] : {std::pair{"settling", 0.7}, std::pair{"asleep", 3.0}})
            benchmark::RegisterBenchmark(("collisions/pile/" + std::string(phase) + "/n:" + std::to_string(n)).c_str(),
                                         [n, from](benchmark::State& s) { run_pile(s, n, from); })
                ->UseRealTime()
                ->Iterations(iterations);
        if (n >= 10000)
            benchmark::RegisterBenchmark(("collisions/pile/settling/threads:2/n:" + std::to_string(n)).c_str(),
                                         [n](benchmark::State& s) { run_pile(s, n, 0.7, 2); })
                ->UseRealTime()
                ->Iterations(iterations);
    }
    for (const std::size_t n : {std::size_t{1000}, std::size_t{10000}, std::size_t{100000}}) {
        for (const bool on : {false, true})
            benchmark::RegisterBenchmark(("collisions/gas/" + std::string(on ? "on" : "off") + "/n:" + std::to_string(n)).c_str(),
                                         [n, on](benchmark::State& s) { run_gas(s, n, on); })
                ->UseRealTime();
        if (n >= 10000)  // the same with collisions on two threads (the scaling)
            benchmark::RegisterBenchmark(("collisions/gas/on/threads:2/n:" + std::to_string(n)).c_str(),
                                         [n](benchmark::State& s) { run_gas(s, n, true, 2); })
                ->UseRealTime();
        if (n == 100000)  // the GUI's target: real time at 1e5 with dt = 2 ms on two threads
            for (const int threads : {1, 2})
                benchmark::RegisterBenchmark(
                    ("collisions/gas/on/dt:2ms/" + std::string(threads == 2 ? "threads:2/" : "") + "n:100000").c_str(),
                    [n, threads](benchmark::State& s) { run_gas(s, n, true, threads, 2e-3); })
                    ->UseRealTime();
        benchmark::RegisterBenchmark(("collisions/pairs/grid/n:" + std::to_string(n)).c_str(),
                                     [n](benchmark::State& s) { run_pairs(s, n, true); })
            ->UseRealTime();
        if (n <= 10000)  // 1e5 all-pairs: 5e9 box tests a call
            benchmark::RegisterBenchmark(("collisions/pairs/all_pairs/n:" + std::to_string(n)).c_str(),
                                         [n](benchmark::State& s) { run_pairs(s, n, false); })
                ->UseRealTime();
    }
}

}  // namespace pl::bench
