// The production stepping kernel. Bit-identical to the generic one (simulation.cpp), faster:
//  * threads: the particles are split into contiguous ranges run on the shared ThreadPool; each
//    range collects its own events, which are appended in range order, so events, ledger and
//    state are the same for any thread count. One range per thread, the same range every step
//    (its data stays in that core's cache); a range a late worker has not started is taken by
//    the caller (ThreadPool), so a thread the OS delays holds up the step by one range at most;
//  * within a range, chunks of `fast_chunk` particles in two phases:
//    1. flight: a branch-free loop over the structure-of-arrays state runs the scene's fixed-step
//       method (the same integrators.hpp and forces.hpp code the generic path runs, so the same
//       floating-point operations in the same order) and keeps the result only where the
//       particle was free (not resting, not frozen), ends the step inside every wall and stays
//       finite; otherwise the state is left untouched and the particle is flagged. Selects,
//       not branches, so it vectorises when the forces do (no wind, drag none/linear/quadratic);
//    2. contact: flagged particles wait in a batch (from several chunks, in particle order) and
//       are re-stepped from their untouched state: a free particle crossing one wall, and one
//       resting on one wall, in branch-free lanes that repeat ParticleStepper::advance's
//       operations for those cases; everything else (corners, rests, stops, releases,
//       freezing) by the generic ParticleStepper itself.
//    Particles at rest are handled per chunk before phase 2: a chunk whose particles all rest
//    with v = +0 on walls that hold a particle still (without wind; found once by running the
//    slide) is skipped, since the step would change no bit of it; a chunk with many resting
//    particles slides them in place, in a vector pass (the slide of one lane is the same
//    function the contact lanes run), and skips phase 1 when all of them rest.
//    Methods without a fixed-step flight phase (adaptive Dormand-Prince, exponential) take
//    phase 2 for every particle, still split across threads; with the sphere correlation (it
//    calls pow) or wind at points inside the step, the same phases run as scalar loops.
//  * several steps per call (Simulation::step_n): each range advances block by block, every
//    block of block_particles through all the steps while it is in cache, instead of streaming
//    the whole state once per step; each step's events and frozen particles are kept apart and
//    merged step by step, range by range, so the result is that of one step at a time.
// Where the parts are: fast_kernel.cpp (ranges, threads, the kernel for each method and term list),
// range_stepper.hpp (chunks, phase 2's routing, the resting passes),
// flight_chunk.hpp (phase 1), held_lanes.hpp (which particles phase 1 leaves alone),
// contact_lanes.hpp and slide_lane.hpp (phase 2's bounce and slide lanes), lane_math.hpp (the
// branch-free selects they share).
#pragma once

#include "physics/stepping/kernel.hpp"

#include <cstddef>

namespace pl {

constexpr std::size_t fast_chunk = 256;
// Fewer particles than this per range are not worth a hand-over to another thread.
constexpr std::size_t min_particles_per_range = 1024;
// Measured on the 2-vCPU development machine (bench/RESULTS.md): with two ranges per thread a
// worker that wakes a microsecond late had one of its ranges taken by the caller every step,
// whose data was then in the wrong core's cache: 1.12x on two threads at 1e4 particles; with
// one, 1.8x.
constexpr std::size_t ranges_per_thread = 1;
// Above this many particles the state (about 140 bytes each, 37 MB here) streams from memory
// rather than the caches, and phase 1 writes whole vectors (see flight_chunk). Measured: masked
// stores still win at 1e5 particles, whole vectors at 1e6.
constexpr std::size_t cache_resident_particles = 1u << 18;
// With several steps per call (Simulation::step_n), each block of about this many particles of a
// range takes all of them before the next block starts. Phase 1 touches about 70 bytes per particle
// (state, drag ledger, flags), so a block (about 570 KB) stays in the core's 1 MB L2 cache.
// Measured on the development machine at 1e6 particles, 32 steps per call: 4.8e8
// particle-steps/s with blocks of 1024, 5.3e8 with 8192 (smaller blocks also cut the contact
// batches short).
constexpr std::size_t block_particles = 8192;
// The block length step_n uses for a range of n particles: as many blocks of about
// block_particles as the range holds best (a range of 1.2 blocks is one block, not a block and
// a fifth), on chunk boundaries.
std::size_t block_length(std::size_t n);

// The kernel for the model's force terms and method (never null).
StepKernel pick_fast_kernel(const Model& model);

// Threads a `threads` setting means (0 = all hardware threads).
std::size_t thread_count(int threads);
// Number of contiguous particle ranges a step of n particles is split into for a `threads`
// setting: 1 on one thread or below 2 * min_particles_per_range particles.
std::size_t particle_ranges(std::size_t n, int threads);
// First particle of range k of `ranges` (n for k >= ranges).
std::size_t range_begin(std::size_t n, std::size_t ranges, std::size_t k);

// Whether the model's method and drag run the vectorised flight phase (phase 1) at all.
bool has_fast_flight(const Model& model);

}  // namespace pl
