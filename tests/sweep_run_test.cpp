// Running sweeps: the drag-free optimum angle against the closed form, bad points refused before
// anything runs, results independent of the thread count, and Monte Carlo statistics that are
// the same in any shard count.
#include "io/sweep_table.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>
#include <cctype>

namespace pl {
namespace {

std::string optimal_angle_preset() {
    std::ifstream in(std::filesystem::path(PL_SOURCE_DIR) / "presets" / "optimal_angle.json");
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

SweepSpec spec_of(const std::vector<std::string>& axes, const std::string& metrics, double duration_s) {
    SweepSpec spec;
    spec.preset_text = optimal_angle_preset();
    for (const std::string& a : axes) EXPECT_EQ(parse_axis(a, spec.plan.axes.emplace_back()), "") << a;
    EXPECT_EQ(parse_metric_list(metrics, spec.metrics), "");
    spec.duration_s = duration_s;
    return spec;
}

std::vector<std::size_t> all_points(const SweepSpec& spec) { return shard_points({}, spec.plan.point_count()); }

std::string run_to_csv(const SweepSpec& spec, Shard shard, int threads) {
    const PreparedSweep prepared = prepare_sweep(spec, shard_points(shard, spec.plan.point_count()));
    EXPECT_EQ(prepared.error, "");
    SweepRunOptions options;
    options.threads = threads;
    const SweepResults results = run_sweep(prepared, spec.duration_s, options);
    return sweep_csv({sweep_id(spec), spec.plan.point_count(), shard}, spec, prepared, results);
}

TEST(SweepRun, OptimumAngleWithoutDragIs45DegreesAndTheRangeIsTheClosedForm) {
    // R(theta) = v^2 sin(2 theta) / g, launched and landing at the same height: largest at 45
    // degrees, R = v^2 / g. The preset's RK4 is exact on the parabola; the impact time is
    // located within the step.
    const SweepSpec spec =
        spec_of({"launch.elevation_deg=30:60:31", "drag.model=none"}, "range_at_first_impact_m", 6.5);
    const PreparedSweep prepared = prepare_sweep(spec, all_points(spec));
    ASSERT_EQ(prepared.error, "");
    const SweepResults results = run_sweep(prepared, spec.duration_s, {});
    double best = -1.0;
    std::string best_angle;
    for (std::size_t i = 0; i < prepared.points.size(); ++i) {
        const std::optional<double> r = sweep_metrics()[spec.metrics[0]].of(results.points[i].variants[0], 0);
        ASSERT_TRUE(r.has_value());
        const double theta = (30.0 + static_cast<double>(i)) * M_PI / 180.0;
        EXPECT_NEAR(*r, 30.0 * 30.0 * std::sin(2.0 * theta) / 9.81, 1e-9) << "elevation " << 30 + i;
        if (*r > best) best = *r, best_angle = spec.plan.point_values(prepared.points[i])[0];
    }
    EXPECT_EQ(best_angle, "45");  // to the sweep's resolution of 1 degree
}

TEST(SweepRun, WithQuadraticDragTheOptimumIsBelow45Degrees) {
    const SweepSpec spec = spec_of({"launch.elevation_deg=30:50:21", "drag.model=quadratic"}, "range_at_first_impact_m", 6.5);
    const PreparedSweep prepared = prepare_sweep(spec, all_points(spec));
    const SweepResults results = run_sweep(prepared, spec.duration_s, {});
    std::size_t best = 0;
    for (std::size_t i = 1; i < results.points.size(); ++i)
        if (results.points[i].variants[0].particles[0].range_at_first_impact >
            results.points[best].variants[0].particles[0].range_at_first_impact)
            best = i;
    EXPECT_LT(30 + best, 45u);
}

TEST(SweepRun, ABadAxisValueIsRefusedNamingTheFieldAndTheValueBeforeAnythingRuns) {
    const SweepSpec spec = spec_of({"drag.model=quadratic", "drag.cd=0.5,0.4,-0.5"}, "bounces", 1.0);
    const PreparedSweep prepared = prepare_sweep(spec, all_points(spec));
    EXPECT_NE(prepared.error.find("drag.cd"), std::string::npos) << prepared.error;
    EXPECT_NE(prepared.error.find("-0.5"), std::string::npos) << prepared.error;
    EXPECT_NE(prepared.error.find("point 2"), std::string::npos) << prepared.error;
    EXPECT_TRUE(prepared.scenes.empty());
    // A point outside the shard is checked too: every shard refuses the same sweep.
    EXPECT_EQ(prepare_sweep(spec, {0}).error, prepared.error);
    // An unknown path is the reader's unknown key.
    EXPECT_NE(prepare_sweep(spec_of({"drag.cdd=1"}, "bounces", 1.0), {0}).error.find("drag.cdd: unknown key"),
              std::string::npos);
}

TEST(SweepRun, ResultsDoNotDependOnTheThreadCount) {
    const SweepSpec spec = spec_of({"launch.elevation_deg=20:70:6", "drag.model=quadratic,sphere_re"},
                                   "range_at_first_impact_m,apex_height_m,energy_lost_J", 3.0);
    EXPECT_EQ(run_to_csv(spec, {}, 1), run_to_csv(spec, {}, 2));
}

TEST(SweepRun, MonteCarloStatisticsAreTheSameInAnyShardCount) {
    SweepSpec spec = spec_of({}, "range_at_first_impact_m", 6.5);
    ASSERT_EQ(parse_sample("drag.cd=normal(0.47,0.05)", spec.plan.samples.emplace_back()), "");
    spec.plan.sample_count = 40;
    spec.plan.seed = 1;
    const std::string whole = run_to_csv(spec, {}, 0);
    for (std::size_t n : {2u, 3u, 7u})
        for (bool strided : {false, true}) {
            std::vector<SweepFile> files;
            std::vector<std::string> names;
            const std::filesystem::path dir = std::filesystem::temp_directory_path();
            for (std::size_t i = 0; i < n; ++i) {
                const auto file = dir / ("pl_sweep_mc_" + std::to_string(::getpid()) + "_" + std::to_string(i) + ".csv");
                ASSERT_EQ(write_file_atomically(file, run_to_csv(spec, {i, n, strided}, 1)), "");
                std::string error;
                files.push_back(*read_sweep_file(file, error));
                names.push_back(file.string());
                std::filesystem::remove(file);
            }
            std::string error;
            EXPECT_EQ(merge_sweep_files(files, names, error), whole) << n << " shards, strided " << strided;
            EXPECT_EQ(error, "");
        }
    // The statistics from the whole run (and so from every merge above): the range falls as Cd
    // grows, so its spread is not zero and its mean is a quadratic-drag range (below v^2/g).
    std::istringstream in(whole);
    std::string line;
    double sum = 0.0, sum2 = 0.0;
    int n = 0;
    while (std::getline(in, line))
        if (!line.empty() && std::isdigit(static_cast<unsigned char>(line[0]))) {
            const double r = std::stod(line.substr(line.rfind(',') + 1));
            sum += r, sum2 += r * r, ++n;
        }
    ASSERT_EQ(n, 40);
    EXPECT_LT(sum / n, 30.0 * 30.0 / 9.81);
    EXPECT_GT(sum2 / n - (sum / n) * (sum / n), 0.0);
}

}  // namespace
}  // namespace pl
