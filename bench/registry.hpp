// Registration entry points of the benchmark files, called from bench/main.cpp in report order.
#pragma once

#include <cstddef>
#include <string>

namespace pl::bench {

constexpr std::size_t sizes[] = {1000, 10000, 100000, 1000000};

void register_engine_benchmarks();      // engine_bench.cpp
void register_method_benchmarks();      // engine_bench.cpp
void register_baseline_benchmarks();    // oo_baseline.cpp
void register_limit_benchmarks();       // hand_fused.cpp
void register_paired_benchmarks();      // paired_bench.cpp
// "paired/drag_walls/steps:<steps>/n:<n>/threads:<threads>", as registered there.
std::string paired_name(int steps, std::size_t n, int threads);
void register_accuracy_benchmarks();    // accuracy_bench.cpp
void register_collision_benchmarks();   // collision_bench.cpp
void register_collision_paired_benchmarks();  // collision_paired.cpp

// Counter every throughput benchmark reports (a rate: particle-steps per second).
constexpr const char* rate_counter = "particle_steps/s";

}  // namespace pl::bench
