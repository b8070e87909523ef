// The Sweep tab's pure side: its choices become the same plan as the CLI's --axis/--sample text,
// the line plot's series follow the point numbering, and the histogram bins and statistics.
#include "io/sweep_view.hpp"

#include <gtest/gtest.h>

namespace pl {
namespace {

TEST(SweepView, ChoicesBecomeTheCliAxisText) {
    SweepAxisChoice range;
    range.path = "launch.elevation_deg";
    range.low = 10, range.high = 80, range.count = 8;
    EXPECT_EQ(axis_spec(range), "launch.elevation_deg=10:80:8");
    SweepAxisChoice list;
    list.path = "drag.model", list.list = true, list.values = "none,linear";
    EXPECT_EQ(axis_spec(list), "drag.model=none,linear");
    SweepChoices mc;
    mc.sample_path = "drag.cd", mc.a = 0.47, mc.b = 0.05;
    EXPECT_EQ(sample_spec(mc), "drag.cd=normal(0.47,0.05)");
}

TEST(SweepView, SpecFromChoicesParsesLikeTheCli) {
    SweepChoices c;
    c.first.low = 10, c.first.high = 80, c.first.count = 8;
    c.two_axes = true;
    c.second.path = "drag.model", c.second.list = true, c.second.values = "none,quadratic";
    SweepSpec spec;
    ASSERT_EQ(spec_from_choices(c, "{}", spec), "");
    ASSERT_EQ(spec.plan.axes.size(), 2u);
    EXPECT_EQ(spec.plan.point_count(), 16u);
    EXPECT_EQ(spec.metrics.size(), sweep_metrics().size());
    EXPECT_EQ(*numeric_values(spec.plan.axes[0]), (std::vector<double>{10, 20, 30, 40, 50, 60, 70, 80}));
    EXPECT_FALSE(numeric_values(spec.plan.axes[1]));

    c.second.path = c.first.path;
    EXPECT_NE(spec_from_choices(c, "{}", spec).find("first axis already"), std::string::npos);
    c.two_axes = false;
    c.first.count = 0;
    EXPECT_NE(spec_from_choices(c, "{}", spec), "");  // parse_axis's message names the axis
    c.monte_carlo = true, c.samples = 50, c.seed = 7;
    ASSERT_EQ(spec_from_choices(c, "{}", spec), "");
    EXPECT_EQ(spec.plan.point_count(), 50u);
    EXPECT_EQ(spec.plan.seed, 7u);
}

TEST(SweepView, LineSeriesOnePerValueOfTheSecondAxis) {
    SweepChoices c;
    c.first.low = 0, c.first.high = 2, c.first.count = 3;
    c.two_axes = true;
    c.second.path = "drag.model", c.second.list = true, c.second.values = "none,linear";
    SweepSpec spec;
    ASSERT_EQ(spec_from_choices(c, "{}", spec), "");
    PreparedSweep prepared;
    for (std::size_t p = 0; p < 6; ++p) prepared.points.push_back(p);
    // Point p = 2 * elevation index + model index; point 3 has no value.
    const std::vector<std::optional<double>> values{0.0, 1.0, 10.0, std::nullopt, 20.0, 21.0};
    const std::vector<SweepSeries> s = line_series(spec.plan, prepared, values);
    ASSERT_EQ(s.size(), 2u);
    EXPECT_EQ(s[0].label, "drag.model=none");
    EXPECT_EQ(s[0].x, (std::vector<double>{0, 1, 2}));
    EXPECT_EQ(s[0].y, (std::vector<double>{0, 10, 20}));
    EXPECT_EQ(s[1].points, (std::vector<std::size_t>{1, 5}));
    EXPECT_EQ(s[1].x, (std::vector<double>{0, 2}));
    EXPECT_EQ(best_index(values), std::optional<std::size_t>(5));
}

TEST(SweepView, CellEdgesHalfWayBetweenValues) {
    EXPECT_EQ(cell_edges({10, 20, 40}), (std::vector<double>{5, 15, 30, 50}));
    EXPECT_EQ(cell_edges({3}), (std::vector<double>{2.5, 3.5}));
}

TEST(SweepView, HistogramBinsAndStatistics) {
    const Histogram h = histogram({1.0, 2.0, 2.5, std::nullopt, 5.0}, 4);
    EXPECT_DOUBLE_EQ(h.low, 1.0);
    EXPECT_DOUBLE_EQ(h.width, 1.0);
    EXPECT_EQ(h.counts, (std::vector<std::size_t>{1, 2, 0, 1}));  // the maximum is in the last bin
    EXPECT_EQ(h.missing, 1u);
    EXPECT_DOUBLE_EQ(h.mean, 2.625);
    EXPECT_NEAR(h.sd, 1.70171, 1e-5);  // sqrt(8.6875 / 3)
    const Histogram same = histogram({4.0, 4.0}, 3);
    EXPECT_EQ(same.counts[0], 2u);
}

}  // namespace
}  // namespace pl
