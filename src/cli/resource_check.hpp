// What a headless run will take, estimated before it starts: memory for every variant's
// particle state, and a lower bound on the time its steps take. Runs that cannot fit in the
// memory the machine has, or would take more than a day, are refused with the numbers; runs
// over a minute get a warning with the estimate.
#pragma once

#include <cstdint>
#include <string>

namespace pl::cli {

struct WorkEstimate {
    std::uint64_t particles = 0;
    std::uint64_t variants = 0;
    double steps = 0.0;  // per variant (a double: absurd inputs give 1e300 and more)
};

// Bytes of one particle in one simulation (an upper bound derived from ParticleState), plus
// its initial specification.
std::uint64_t bytes_per_particle_per_variant();
std::uint64_t initial_bytes_per_particle();
double estimated_bytes(const WorkEstimate& w);
// Lower bound on the run time, s, from the fastest rates measured (README, Performance).
double estimated_seconds(const WorkEstimate& w);
// MemAvailable from /proc/meminfo, bytes; 0 when unknown.
std::uint64_t available_memory_bytes();

// Empty when the work may run; else the refusal, with the numbers. Prints the warning for
// long runs to stderr, prefixed by the command.
std::string check_work(const std::string& command, const WorkEstimate& w);

}  // namespace pl::cli
