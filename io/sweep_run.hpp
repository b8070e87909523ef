// Running a sweep: every point of the plan becomes a scene (the preset's JSON with the point's
// values set through the `--set` paths, then read by the preset reader), every point is
// validated before any runs, and the points of a shard run one scene per thread, each scene on
// one thread (physics/studies/metrics.hpp's comparison), so results do not depend on the
// thread count.
#pragma once

#include "io/sweep_plan.hpp"
#include "physics/studies/metrics.hpp"

#include <atomic>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace pl {

// One metric a sweep can report per scene, variant and particle: the compare metrics, named
// as in `particle-lab compare --json`.
struct SweepMetric {
    const char* name;
    const char* meaning;
    std::optional<double> (*of)(const VariantMetrics& m, std::size_t particle);
};
const std::vector<SweepMetric>& sweep_metrics();
// "a,b" -> indices into sweep_metrics(); an error names the unknown metric and lists the known.
std::string parse_metric_list(const std::string& text, std::vector<std::size_t>& out);

struct SweepSpec {
    std::string preset_text;  // the preset file's contents
    SweepPlan plan;
    std::vector<std::size_t> metrics;  // indices into sweep_metrics()
    double duration_s = 5.0;
    std::size_t particle = 0;  // whose trajectory metrics are reported
};

// A stable identity of the sweep (FNV-1a 64 over the preset and every setting that changes a
// result, as 16 hex digits): shard files carry it so merging refuses shards of another sweep.
std::string sweep_id(const SweepSpec& spec);

// The overrides (`--set` items) that make point `point` out of the preset whose particles[0]
// velocity is `base_velocity` (launch axes); an error names the axis and the value.
std::string point_overrides(const SweepPlan& plan, std::size_t point, const Vec3* base_velocity,
                            std::vector<std::string>& out);

struct PreparedSweep {
    std::vector<std::size_t> points;  // the points to run (a shard's)
    std::vector<Scene> scenes;        // one per entry of `points`
    std::vector<std::string> variant_names;
    std::string error;  // the first bad point: its number, each axis value, and the reader's message
};
// Builds and validates every point of the plan (not only `points`: a bad sweep is refused by
// every shard alike) and keeps the scenes of `points`.
PreparedSweep prepare_sweep(const SweepSpec& spec, const std::vector<std::size_t>& points);

struct SweepRunOptions {
    int threads = 0;  // 0: all hardware threads
    std::function<void(std::size_t done, std::size_t total)> progress;  // from worker threads
    const std::atomic<bool>* cancel = nullptr;
};
struct SweepResults {
    std::vector<Comparison> points;  // in the order of PreparedSweep::points
    bool cancelled = false;
};
SweepResults run_sweep(const PreparedSweep& prepared, double duration_s, const SweepRunOptions& options);

}  // namespace pl
