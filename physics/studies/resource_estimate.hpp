// What a scene will take before it is built: memory for every variant's particle state (and, in
// the variants with collisions, the collision pass's), and a lower bound on the time its steps
// take. The CLI refuses a run past what the machine has
// (src/cli/resource_check.hpp); the GUI refuses to open such a preset and keeps its scene.
#pragma once

#include "physics/model/scene.hpp"

#include <cstdint>
#include <string>

namespace pl {

struct WorkEstimate {
    std::uint64_t particles = 0;
    std::uint64_t variants = 0;
    double steps = 0.0;  // per variant (a double: absurd inputs give 1e300 and more)
    std::uint64_t collision_variants = 0;  // of the variants, those with collisions on
};

// The particles and variants of a scene, with `steps` base steps per variant.
WorkEstimate work_of(const Scene& scene, double steps = 0.0);

// Bytes of one particle in one simulation (an upper bound derived from ParticleState), plus
// its initial specification.
std::uint64_t bytes_per_particle_per_variant();
std::uint64_t initial_bytes_per_particle();
// What the collision pass holds per particle at most, in a variant with collisions on: measured
// (its boxes, the grid's entries, pairs, contacts and islands grow with the particles).
std::uint64_t collision_bytes_per_particle();
double estimated_bytes(const WorkEstimate& w);
// Lower bound on the run time, s, from the fastest rates measured (README, Performance).
double estimated_seconds(const WorkEstimate& w);
// MemAvailable from /proc/meminfo, bytes; 0 when unknown.
std::uint64_t available_memory_bytes();

// Empty when the particle state fits in the memory available; else why not, with the numbers
// ("needs about 276 GB of memory (2000000 particles x 1000 variants x 138 bytes), but ...", and
// the collision pass's share when some variant has collisions on).
std::string memory_refusal(const WorkEstimate& w);

// Text for the messages: "12 s", "3.5 hours"; "2000000 particles x 1000 variants"; "1.2 GB".
std::string duration_text(double seconds);
std::string counts_text(const WorkEstimate& w);
std::string bytes_text(double bytes);

}  // namespace pl
