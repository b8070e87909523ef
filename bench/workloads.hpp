// The physics workloads every benchmark runs: the engine and both references (the
// object-oriented baseline and the hand-fused limit) step the same particles with the same
// dt, drag, restitution and room, so their particle-steps per second compare directly.
#pragma once

#include "physics/model/scene.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace pl::bench {

enum class Workload {
    gravity,           // gravity only (walls still bounce)
    drag_walls,        // gravity + quadratic drag + six walls: the comparison workload
    drag_walls_shear,  // the same in a power-law shear wind
    drag_open,         // drag_walls in a room 1 km wide: no wall is reached, only flight is timed
    drag_rest,         // drag_walls with every ball at rest on the floor (friction 0.3): a settled room
};
const char* to_string(Workload w);

struct WorkloadScene {
    Model model;
    std::vector<ParticleSpec> particles;
    int settle_steps = 0;  // untimed steps after every restart (drag_rest: the balls land on the floor)
};

// n identical tennis balls (57 g, r = 33 mm) spread through a 10 x 6 x 10 m room, launched at
// 0..5 m/s in random directions (seeded); restitution 0.8, no friction (the references have
// none), Cd 0.47 at sea level, dt = 2 ms.
WorkloadScene make_workload(Workload w, std::size_t n, Method method = Method::semi_implicit_euler);

// Every benchmark restarts from the initial particles after this many steps (0.512 s simulated,
// restart excluded from the timing), so all of them measure the same mostly-flying mix rather
// than a room of balls that have come to rest.
constexpr int steps_per_window = 256;

// Per-particle quadratic drag constant 1/2 rho Cd A / m (1/m) of the workload's balls.
double workload_drag_constant(const Model& m, const ParticleSpec& p);

// 1 and, on a machine with more, all hardware threads.
std::vector<int> thread_settings();

// "1k", "10k", "1M" ...
std::string size_label(std::size_t n);

}  // namespace pl::bench
