// The plot widget's pure math: nice ticks, their labels, and per-column decimation.
#include "ui/plot_math.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace pl::ui {
namespace {

bool is_one_two_five(double step) {
    const double mantissa = step / std::pow(10.0, std::floor(std::log10(step)));
    return std::abs(mantissa - 1) < 1e-9 || std::abs(mantissa - 2) < 1e-9 || std::abs(mantissa - 5) < 1e-9;
}

TEST(NiceTicks, StepsAreOneTwoOrFiveTimesAPowerOfTen) {
    for (double span : {1e-7, 3.3e-4, 0.07, 0.9, 1.0, 2.5, 7.3, 13.0, 99.0, 1234.5, 6.02e23}) {
        for (int target : {3, 5, 8}) {
            const double step = nice_step(span, target);
            ASSERT_GT(step, 0.0) << span;
            EXPECT_TRUE(is_one_two_five(step)) << "span " << span << " step " << step;
            const double intervals = span / step;
            EXPECT_GE(intervals, target / 2.5) << span;  // about `target` intervals, never wildly off
            EXPECT_LE(intervals, target * 2.5) << span;
        }
    }
}

TEST(NiceTicks, KnownRanges) {
    const Ticks t = nice_ticks(0.0, 10.0, 5);
    EXPECT_EQ(t.step, 2.0);
    EXPECT_EQ(t.values, (std::vector<double>{0, 2, 4, 6, 8, 10}));
    const Ticks u = nice_ticks(-0.013, 0.052, 6);
    EXPECT_DOUBLE_EQ(u.step, 0.01);
    ASSERT_EQ(u.values.size(), 7u);  // -0.01, 0, ..., 0.05
    EXPECT_DOUBLE_EQ(u.values.front(), -0.01);
    EXPECT_DOUBLE_EQ(u.values.back(), 0.05);
}

TEST(NiceTicks, TicksLieInsideTheRangeAndZeroIsExact) {
    const Ticks t = nice_ticks(-0.3, 0.3, 6);
    for (double v : t.values) {  // k * step may differ from an end by rounding only
        EXPECT_GE(v, -0.3 - 1e-12);
        EXPECT_LE(v, 0.3 + 1e-12);
    }
    EXPECT_EQ(t.values.size(), 7u);
    EXPECT_NE(std::find(t.values.begin(), t.values.end(), 0.0), t.values.end());
    EXPECT_TRUE(nice_ticks(1.0, 1.0, 5).values.empty());  // empty range: no ticks, no hang
    EXPECT_TRUE(nice_ticks(0.0, INFINITY, 5).values.empty());
}

TEST(TickLabels, JustEnoughDigitsToTellNeighboursApart) {
    EXPECT_EQ(format_tick(0.0, 0.5), "0");
    EXPECT_EQ(format_tick(2.0, 0.5), "2.0");
    EXPECT_EQ(format_tick(2.5, 0.5), "2.5");
    EXPECT_EQ(format_tick(40.0, 20.0), "40");
    EXPECT_EQ(format_tick(-0.02, 0.01), "-0.02");
    EXPECT_EQ(format_tick(3e-6, 1e-6), "3e-06");
    EXPECT_EQ(format_tick(2e7, 5e6), "2.0e+07");
}

// The kinetic energy of an elastic gas is constant to round-off: its plot spans 87.4694 J +- 1e-9.
// Every label of such an axis must still differ from its neighbours (they once all read
// "8.746940e+01", the mantissa cut at six digits).
TEST(TickLabels, DistinctOnASpanOfRoundOffAroundALargeValue) {
    for (const double span : {1e-5, 1e-7, 1e-9, 1e-11}) {
        const double lo = 87.469401234, hi = lo + span;
        const Ticks ticks = nice_ticks(lo, hi, 4);
        ASSERT_GE(ticks.values.size(), 2u) << span;
        for (std::size_t i = 1; i < ticks.values.size(); ++i)
            EXPECT_NE(format_tick(ticks.values[i], ticks.step), format_tick(ticks.values[i - 1], ticks.step))
                << "span " << span << ": " << format_tick(ticks.values[i], ticks.step);
    }
}

// The same axes labelled as an offset plus short labels: each label at most 8 characters, and
// offset + label gives the tick's value to within a tenth of a step. Ordinary axes keep their
// plain labels.
TEST(TickLabels, AnAxisOfRoundOffReadsAsAnOffsetPlusShortLabels) {
    const std::pair<double, double> axes[] = {{87.469401234, 1e-5},   {87.469401234, 1e-7},  {87.469401234, 1e-9},
                                              {87.469401234, 1e-11},  {-87.469401234, 1e-9}, {2.5e7, 1e-1},
                                              {2.5e7, 1e-4},          {0.123456789, 1e-9},   {0.123456789, 1e-12}};
    for (const auto& [lo, span] : axes) {
        const Ticks ticks = nice_ticks(lo, lo + span, 4);
        const TickLabels labels = label_ticks(ticks);
        SCOPED_TRACE(std::to_string(lo) + " + " + std::to_string(span));
        ASSERT_FALSE(labels.offset.empty());
        ASSERT_EQ(labels.labels.size(), ticks.values.size());
        const double offset = std::stod(labels.offset);
        for (std::size_t i = 0; i < ticks.values.size(); ++i) {
            EXPECT_LE(labels.labels[i].size(), 8u) << labels.labels[i];
            EXPECT_NEAR(offset + std::stod(labels.labels[i]), ticks.values[i], 0.1 * ticks.step) << labels.labels[i];
            if (i > 0) {
                EXPECT_NE(labels.labels[i], labels.labels[i - 1]);
            }
        }
    }
    for (const auto& [lo, hi] : {std::pair{0.0, 10.0}, std::pair{87.4, 87.5}, std::pair{-2.0, 3.0}, std::pair{990.0, 1010.0}}) {
        const Ticks ticks = nice_ticks(lo, hi, 5);
        const TickLabels labels = label_ticks(ticks);
        EXPECT_TRUE(labels.offset.empty()) << lo << " " << labels.offset;
        for (std::size_t i = 0; i < ticks.values.size(); ++i) EXPECT_EQ(labels.labels[i], format_tick(ticks.values[i], ticks.step));
    }
}

TEST(LogTicks, DecadesAndFinerMarksOnShortRanges) {
    const Ticks wide = log_ticks(1e-9, 1e-1);
    EXPECT_EQ(wide.values.size(), 9u);  // 1e-9 ... 1e-1
    const Ticks narrow = log_ticks(0.15, 6.0);
    EXPECT_EQ(narrow.values, (std::vector<double>{0.2, 0.5, 1.0, 2.0, 5.0}));
}

TEST(DecimateM4, KeepsExtremesOrderAndAtMostFourPointsPerColumn) {
    const std::size_t n = 100'000;
    std::vector<double> xs(n), ys(n);
    for (std::size_t i = 0; i < n; ++i) {
        xs[i] = static_cast<double>(i) * 1e-3;
        ys[i] = std::sin(xs[i] * 7.0) + ((i % 997) == 0 ? 3.0 : 0.0);
    }
    std::vector<PlotPoint> out;
    const int columns = 800;
    decimate_m4(xs.data(), ys.data(), n, 0.0, xs.back(), columns, out);
    EXPECT_LE(out.size(), static_cast<std::size_t>(4 * columns + 8));
    double top = -INFINITY, bottom = INFINITY;
    for (std::size_t i = 0; i < out.size(); ++i) {
        if (i > 0) {
            ASSERT_LT(out[i - 1].x, out[i].x);
        }
        top = std::max(top, out[i].y);
        bottom = std::min(bottom, out[i].y);
    }
    EXPECT_EQ(top, *std::max_element(ys.begin(), ys.end()));
    EXPECT_EQ(bottom, *std::min_element(ys.begin(), ys.end()));
    EXPECT_EQ(out.front().x, 0.0);
    EXPECT_EQ(out.back().x, xs.back());
}

TEST(DecimateM4, AWindowAddsOneNeighbourEachSideAndShortDataPassesThrough) {
    std::vector<double> xs{0, 1, 2, 3, 4, 5}, ys{0, 1, 0, 1, 0, 1};
    std::vector<PlotPoint> out;
    decimate_m4(xs.data(), ys.data(), xs.size(), 1.5, 3.5, 100, out);
    ASSERT_EQ(out.size(), 4u);  // 1, 2, 3, 4
    EXPECT_EQ(out.front().x, 1.0);
    EXPECT_EQ(out.back().x, 4.0);
}

TEST(DecimateM4, NonFiniteSamplesBreakTheLine) {
    std::vector<double> xs{0, 1, 2}, ys{0, NAN, 2};
    std::vector<PlotPoint> out;
    decimate_m4(xs.data(), ys.data(), xs.size(), 0, 2, 100, out);
    ASSERT_EQ(out.size(), 3u);
    EXPECT_TRUE(std::isnan(out[1].y));
}

TEST(ConstantRange, ConstantDataSpansZeroToTheValue) {
    double lo = 0.033, hi = 0.033;  // a ball at rest on the floor
    constant_range(lo, hi);
    EXPECT_EQ(lo, 0.0);
    EXPECT_EQ(hi, 0.033);
    const Ticks ticks = nice_ticks(lo, hi, 5);
    ASSERT_GE(ticks.values.size(), 3u);
    for (std::size_t i = 1; i < ticks.values.size(); ++i)  // distinct labels, none of them "3.3e-02" five times
        EXPECT_NE(format_tick(ticks.values[i], ticks.step), format_tick(ticks.values[i - 1], ticks.step));
    lo = hi = 0.0;  // at rest: speed exactly 0
    constant_range(lo, hi);
    EXPECT_EQ(lo, -1.0);
    EXPECT_EQ(hi, 1.0);
    lo = hi = -2.0;
    constant_range(lo, hi);
    EXPECT_EQ(lo, -2.0);
    EXPECT_EQ(hi, 0.0);
    lo = 1.0, hi = 1.0 + 1e-12;  // varying data, however little, is shown as it is
    constant_range(lo, hi);
    EXPECT_EQ(hi, 1.0 + 1e-12);
}

TEST(Coincide, LinesWithinAPixelCoincideWhateverTheirSampleTimes) {
    const std::vector<PlotPoint> a{{0.0, 1.0}, {1.0, 2.0}, {2.0, 3.0}};
    std::vector<PlotPoint> b{{0.0, 1.0004}, {0.5, 1.5}, {2.0, 3.0}};  // other times, same line
    EXPECT_TRUE(coincide(a, b, 1e-3, 0.0));
    b[1].y = 1.6;
    EXPECT_FALSE(coincide(a, b, 1e-3, 0.0));
    EXPECT_TRUE(coincide(a, b, 1e-3, 0.34));  // one point of three off: allowed at a third
    b[1].y = std::nan("");  // a gap in b only
    EXPECT_FALSE(coincide(a, b, 1e-3, 0.0));
    EXPECT_FALSE(coincide(a, std::vector<PlotPoint>{{3.0, 4.0}}, 1e-3, 0.0));  // beyond a's span
}

}  // namespace
}  // namespace pl::ui
