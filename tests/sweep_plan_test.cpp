// The sweep plan: axis specs, point numbering, seeded samples that depend on (seed, k) alone,
// and shards that split the points into disjoint slices covering them all.
#include "io/sweep_plan.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

namespace pl {
namespace {

SweepAxis axis(const std::string& spec) {
    SweepAxis a;
    EXPECT_EQ(parse_axis(spec, a), "") << spec;
    return a;
}

TEST(SweepPlan, RangeAxisHasCountValuesWithBothEndsExact) {
    const SweepAxis a = axis("launch.elevation_deg=10:80:71");
    ASSERT_EQ(a.values.size(), 71u);
    EXPECT_EQ(a.values.front(), "10");
    EXPECT_EQ(a.values[35], "45");  // whole steps stay whole: 10 + 70 * 35 / 70
    EXPECT_EQ(a.values.back(), "80");
    const SweepAxis cd = axis("drag.cd=0.3:0.7:9");
    EXPECT_EQ(cd.values.front(), "0.3");
    EXPECT_EQ(cd.values.back(), "0.7");
    EXPECT_EQ(axis("drag.cd=0.5:0.9:1").values, std::vector<std::string>{"0.5"});
}

TEST(SweepPlan, ListAxisKeepsCommasInsideBrackets) {
    EXPECT_EQ(axis("drag.model=none,linear,quadratic,sphere_re").values,
              (std::vector<std::string>{"none", "linear", "quadratic", "sphere_re"}));
    EXPECT_EQ(axis("particles[0].velocity=[5,5,0],[1,2,3]").values, (std::vector<std::string>{"[5,5,0]", "[1,2,3]"}));
}

TEST(SweepPlan, BadSpecsAreRefusedNamingTheAxis) {
    SweepAxis a;
    EXPECT_NE(parse_axis("drag.cd=0.3:0.7", a).find("drag.cd"), std::string::npos);
    EXPECT_NE(parse_axis("drag.cd=0.3:x:4", a).find("'0.3:x:4'"), std::string::npos);
    EXPECT_NE(parse_axis("drag.cd=1:2:0", a), "");
    EXPECT_NE(parse_axis("drag.cd", a), "");
    EXPECT_NE(parse_axis("launch.azimuth=1,2", a).find("launch.azimuth"), std::string::npos);
    EXPECT_NE(parse_sample("drag.cd=gauss(1,2)", a).find("drag.cd"), std::string::npos);
    EXPECT_NE(parse_sample("drag.cd=normal(1,-2)", a).find("standard deviation"), std::string::npos);
    EXPECT_NE(parse_sample("drag.cd=uniform(2,1)", a), "");
}

TEST(SweepPlan, PointsAreRowMajorWithSamplesFastest) {
    SweepPlan plan;
    plan.axes = {axis("a=1,2"), axis("b=x,y,z")};
    SweepAxis s;
    ASSERT_EQ(parse_sample("c=uniform(0,1)", s), "");
    plan.samples = {s};
    plan.sample_count = 2;
    ASSERT_EQ(plan.point_count(), 12u);
    EXPECT_EQ(plan.column_names(), (std::vector<std::string>{"a", "b", "c"}));
    const std::vector<std::string> p7 = plan.point_values(7);  // grid point 3 = (a=2, b=x), sample 1
    EXPECT_EQ(p7[0], "2");
    EXPECT_EQ(p7[1], "x");
    EXPECT_EQ(p7[2], plan.point_values(1)[2]);  // sample 1 of another grid point: the same value
}

TEST(SweepPlan, SampleKDependsOnSeedAndKAlone) {
    SweepAxis s;
    ASSERT_EQ(parse_sample("drag.cd=normal(0.47,0.05)", s), "");
    // Drawn in reverse order, or one at a time in a fresh call: the same values.
    std::vector<double> forward, backward(100);
    for (std::size_t k = 0; k < 100; ++k) forward.push_back(sample_value(s, 1, 0, k));
    for (std::size_t k = 100; k-- > 0;) backward[k] = sample_value(s, 1, 0, k);
    EXPECT_EQ(forward, backward);
    EXPECT_NE(sample_value(s, 2, 0, 5), sample_value(s, 1, 0, 5));  // the seed matters
    EXPECT_NE(sample_value(s, 1, 1, 5), sample_value(s, 1, 0, 5));  // so does the axis
}

TEST(SweepPlan, NormalAndUniformSamplesHaveTheirMoments) {
    SweepAxis n, u;
    ASSERT_EQ(parse_sample("x=normal(0.47,0.05)", n), "");
    ASSERT_EQ(parse_sample("x=uniform(2,3)", u), "");
    const std::size_t count = 20000;
    double sum = 0, sum2 = 0, usum = 0, umin = 10, umax = -10;
    for (std::size_t k = 0; k < count; ++k) {
        const double x = sample_value(n, 7, 0, k);
        sum += x;
        sum2 += x * x;
        const double y = sample_value(u, 7, 0, k);
        usum += y;
        umin = std::min(umin, y);
        umax = std::max(umax, y);
    }
    const double mean = sum / count, sd = std::sqrt(sum2 / count - mean * mean);
    // Standard errors: 0.05 / sqrt(n) = 3.5e-4 for the mean, about sd / sqrt(2 n) = 2.5e-4 for
    // the sd; 4 standard errors each.
    EXPECT_NEAR(mean, 0.47, 4 * 3.5e-4);
    EXPECT_NEAR(sd, 0.05, 4 * 2.5e-4);
    EXPECT_NEAR(usum / count, 2.5, 4 * std::sqrt(1.0 / 12.0 / count));
    EXPECT_GE(umin, 2.0);
    EXPECT_LT(umax, 3.0);
}

TEST(SweepPlan, ShardsAreDisjointAndCoverEveryPoint) {
    for (bool strided : {false, true})
        for (std::size_t total : {0u, 1u, 7u, 71u, 100u})
            for (std::size_t n = 1; n <= 8; ++n) {
                std::vector<int> hits(total, 0);
                for (std::size_t i = 0; i < n; ++i)
                    for (std::size_t p : shard_points({i, n, strided}, total)) ++hits.at(p);
                EXPECT_EQ(std::count(hits.begin(), hits.end(), 1), static_cast<long>(total))
                    << total << " points, " << n << " shards, strided " << strided;
            }
    EXPECT_EQ(shard_points({1, 3, false}, 10), (std::vector<std::size_t>{3, 4, 5}));
    EXPECT_EQ(shard_points({1, 3, true}, 10), (std::vector<std::size_t>{1, 4, 7}));
    Shard s;
    EXPECT_EQ(parse_shard("2/3", false, s), "");
    EXPECT_EQ(s.index, 2u);
    EXPECT_NE(parse_shard("3/3", false, s).find("'3/3'"), std::string::npos);
    EXPECT_NE(parse_shard("1", false, s), "");
}

}  // namespace
}  // namespace pl
