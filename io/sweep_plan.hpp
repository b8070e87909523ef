// A parameter sweep's plan: the axes over preset fields, the seeded random samples, the points
// they span and the shards that split them. Pure bookkeeping; io/sweep_run.hpp turns a point
// into a scene through the same `--set` paths (io/preset_overrides.hpp) and runs it.
//
// Points are numbered 0 .. point_count() - 1: the grid axes in row-major order (the first axis
// varies slowest), and within each grid point the samples 0 .. sample_count - 1. A point's
// values depend on its number alone, so any shard computes exactly what the whole run does.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace pl {

enum class Distribution { normal, uniform };

// The launch axes set particles[0].velocity from a speed and an elevation over the horizontal
// (the preset's horizontal direction is kept; +x when it has none).
constexpr const char* launch_speed_path = "launch.speed_mps";
constexpr const char* launch_elevation_path = "launch.elevation_deg";
bool is_launch_path(const std::string& path);

struct SweepAxis {
    std::string path;                 // a preset path (drag.cd, particles[0].mass) or a launch axis
    std::vector<std::string> values;  // grid axis: each value as JSON text, in order
    bool sampled = false;             // a --sample axis: values drawn from the distribution
    Distribution distribution = Distribution::normal;
    double a = 0.0, b = 0.0;          // normal: mean, standard deviation; uniform: low, high
    std::string spec;                 // as written after the path's '=' (sweep identity, messages)
};

struct SweepPlan {
    std::vector<SweepAxis> axes;     // grid axes
    std::vector<SweepAxis> samples;  // sampled axes
    std::size_t sample_count = 0;    // samples per grid point (0: no sampled axes)
    std::uint64_t seed = 1;

    std::size_t point_count() const;
    std::vector<std::string> column_names() const;  // grid axes' paths, then sampled ones
    // Each column's value text at `point`: a grid axis's value or a sample's shortest round-trip.
    std::vector<std::string> point_values(std::size_t point) const;
};

// `--axis PATH=LOW:HIGH:COUNT` (COUNT evenly spaced values, both ends included) or
// `--axis PATH=V1,V2,...` (a list; commas inside [] or {} belong to the value). Returns an
// error naming the option and what is wrong, or "".
std::string parse_axis(const std::string& spec, SweepAxis& out);
// `--sample PATH=normal(MEAN,SD)` or `PATH=uniform(LOW,HIGH)`.
std::string parse_sample(const std::string& spec, SweepAxis& out);

// Sample k of the sampled axis number `axis_index`: a function of (seed, axis_index, k) alone
// (a counter-based generator, no state carried from one sample to the next).
double sample_value(const SweepAxis& axis, std::uint64_t seed, std::size_t axis_index, std::size_t k);

// `--shard I/N`: the I-th of N slices (0 <= I < N), contiguous blocks of point numbers or every
// N-th point from I (strided).
struct Shard {
    std::size_t index = 0, count = 1;
    bool strided = false;
    bool whole() const { return count == 1; }
};
std::string parse_shard(const std::string& text, bool strided, Shard& out);
std::vector<std::size_t> shard_points(const Shard& shard, std::size_t total);

}  // namespace pl
