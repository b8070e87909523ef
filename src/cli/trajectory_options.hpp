// What `run` checks before it writes a trajectory: the --particles filter and the output size.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace pl::cli {

// "0,3-5" -> {0, 3, 4, 5} (sorted, no duplicates), each < `count`; returns an error naming
// --particles and the bad item, or empty.
std::string parse_particle_list(const std::string& text, std::size_t count, std::vector<std::size_t>& out);

// Trajectory outputs beyond this many bytes get a warning before the run starts.
constexpr std::uint64_t trajectory_warning_bytes = 1ull << 30;

// Rows a run writes at most: the initial and final state plus one per K base steps, per
// particle and variant (a variant with a coarser dt writes fewer).
std::uint64_t trajectory_rows_bound(std::uint64_t base_steps, std::uint64_t every, std::uint64_t particles,
                                    std::uint64_t variants);

// The warning for an output of `bytes` (empty below trajectory_warning_bytes): its size, and
// how to make it smaller.
std::string trajectory_size_warning(const std::string& path, std::uint64_t bytes);

}  // namespace pl::cli
