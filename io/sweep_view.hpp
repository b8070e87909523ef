// What the GUI's Sweep tab needs from a sweep, kept pure so it is tested without a window: the
// tab's choices turned into the same plan `particle-lab sweep` parses (its --axis / --sample
// text), one metric's values per point, the line plot's series, the heat map's cells and the
// Monte Carlo histogram.
#pragma once

#include "io/sweep_run.hpp"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace pl {

// One grid axis as the tab edits it: a range (count values from low to high, both included) or
// a list typed as `particle-lab sweep --axis PATH=V1,V2,...` takes it.
struct SweepAxisChoice {
    std::string path = launch_elevation_path;
    bool list = false;
    double low = 10.0, high = 80.0;
    int count = 8;
    std::string values;  // list: "none,linear,quadratic"
};

struct SweepChoices {
    bool monte_carlo = false;
    SweepAxisChoice first;
    bool two_axes = false;
    SweepAxisChoice second;
    // Monte Carlo: one sampled path
    std::string sample_path = "drag.cd";
    Distribution distribution = Distribution::normal;
    double a = 0.47, b = 0.05;  // normal: mean, sd; uniform: low, high
    std::size_t samples = 200;
    std::uint64_t seed = 1;
    double duration_s = 5.0;
};

// The `--axis` text of a choice ("launch.elevation_deg=10:80:8", "drag.model=none,linear").
std::string axis_spec(const SweepAxisChoice& axis);
// The `--sample` text of the Monte Carlo choice ("drag.cd=normal(0.47,0.05)").
std::string sample_spec(const SweepChoices& choices);
// The spec the tab runs: the preset text, the plan parsed from the choices by parse_axis /
// parse_sample, every metric (as `particle-lab sweep` without --metrics). An error names the
// field and what is wrong, or "".
std::string spec_from_choices(const SweepChoices& choices, const std::string& preset_text, SweepSpec& out);

// Metric `metric` (index into sweep_metrics()) of variant `variant` at each prepared point, in
// the order of PreparedSweep::points; empty where the scene has none or the run was cancelled.
std::vector<std::optional<double>> metric_values(const SweepSpec& spec, const PreparedSweep& prepared,
                                                 const SweepResults& results, std::size_t metric, std::size_t variant);

// A grid axis's values as numbers, or none when one is not a number (drag.model).
std::optional<std::vector<double>> numeric_values(const SweepAxis& axis);

// The line plot: metric against the first axis (its values, or 0, 1, ... for a list of names),
// one series per value of the second axis; `points` are the sweep's point numbers.
struct SweepSeries {
    std::string label;  // the second axis's "path=value", or "" with one axis
    std::vector<double> x, y;
    std::vector<std::size_t> points;
};
std::vector<SweepSeries> line_series(const SweepPlan& plan, const PreparedSweep& prepared,
                                     const std::vector<std::optional<double>>& values);

// Cell edges of a heat map axis: half way between neighbouring values, the ends mirrored
// (values sorted ascending; one value gets a cell of width 1 around it).
std::vector<double> cell_edges(const std::vector<double>& values);

struct Histogram {
    double low = 0.0, width = 1.0;  // bin i covers [low + i width, low + (i + 1) width)
    std::vector<std::size_t> counts;
    std::size_t missing = 0;  // points without the metric
    double mean = 0.0, sd = 0.0;  // of the present values (sample standard deviation)
};
// `bins` equal bins over [min, max] of the present values; the maximum falls in the last bin.
Histogram histogram(const std::vector<std::optional<double>>& values, std::size_t bins);

// The index of the largest present value, or none.
std::optional<std::size_t> best_index(const std::vector<std::optional<double>>& values);

}  // namespace pl
