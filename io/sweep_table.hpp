// A sweep's output: one row per point, variant and metric, as CSV (shards and merged results)
// or JSON. A CSV file opens with two comment lines naming the sweep and the slice it holds:
//
//     # particle-lab sweep 3f2a9c0d4b1e7a55
//     # points 71 shard 0/3 contiguous
//     point,launch.elevation_deg,variant,metric,value
//     0,10,0,range_at_first_impact_m,31.24...
//
// so that sweep-merge can refuse shards of another sweep and check that every point is there.
// The whole run is shard 0/1; merging shards writes exactly that file, byte for byte.
#pragma once

#include "io/sweep_plan.hpp"
#include "io/sweep_run.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace pl {

struct SweepHeader {
    std::string id;           // sweep_id()
    std::size_t points = 0;   // points in the whole sweep
    Shard shard;              // the slice this file holds
};

// The rows of a shard's results (or the whole run's) as CSV, header included.
std::string sweep_csv(const SweepHeader& header, const SweepSpec& spec, const PreparedSweep& prepared,
                      const SweepResults& results);
// The same rows as one JSON document (numbers as numbers, an empty metric as null).
std::string sweep_json(const SweepHeader& header, const SweepSpec& spec, const PreparedSweep& prepared,
                       const SweepResults& results);

// A CSV sweep file read back: its header, its column line and its rows kept as written.
struct SweepFile {
    SweepHeader header;
    std::string columns;
    std::vector<std::pair<std::size_t, std::string>> rows;  // point number, the row's line
};
// Reads and checks one file: the header, and that it holds every point of its slice with the
// same number of rows each. An error names the file and what is wrong.
std::optional<SweepFile> read_sweep_file(const std::filesystem::path& file, std::string& error);

// Joins the shards of one sweep (any order) into the whole run's CSV; refuses shards of
// different sweeps or slicings, a missing or repeated shard. An error says which.
std::string merge_sweep_files(const std::vector<SweepFile>& shards, const std::vector<std::string>& names,
                              std::string& error);

// The same shards joined into the JSON document `sweep --json` writes for the whole run, byte
// for byte.
std::string merged_sweep_json(const std::vector<SweepFile>& shards, const std::vector<std::string>& names,
                              std::string& error);

// Writes `text` to `file` whole or not at all (io/atomic_output.hpp: a unique temporary file
// beside it, synced and renamed over it). Returns an error or "".
std::string write_file_atomically(const std::filesystem::path& file, const std::string& text);

}  // namespace pl
