// The plots' bounded history: memory stays bounded, time order is kept, extremes survive.
#include "ui/plot_history.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace pl::ui {
namespace {

TEST(SampleSeries, NeverHoldsMoreThanItsCapacityOverALongRun) {
    SampleSeries s(1000);  // rounded up to 1000 (a multiple of 8)
    EXPECT_EQ(s.capacity(), 1000u);
    for (int i = 0; i < 1'000'000; ++i) {
        s.push(i * 0.001, std::sin(i * 0.01));
        ASSERT_LE(s.size(), s.capacity());
    }
    EXPECT_GE(s.size(), s.capacity() / 2);  // compaction keeps it well used
}

TEST(SampleSeries, KeepsTimesAscendingAndTheNewestSamplesExact) {
    SampleSeries s(64);
    for (int i = 0; i < 10'000; ++i) s.push(i, i % 7);
    for (std::size_t i = 1; i < s.size(); ++i) ASSERT_LT(s.times()[i - 1], s.times()[i]);
    // The newer half is never decimated: the last 32 samples are the last 32 pushed.
    for (std::size_t k = 0; k < 32; ++k) {
        const double t = 9999.0 - static_cast<double>(k);
        EXPECT_EQ(s.times()[s.size() - 1 - k], t);
        EXPECT_EQ(s.values()[s.size() - 1 - k], static_cast<double>(static_cast<int>(t) % 7));
    }
    EXPECT_EQ(s.times()[0], 0.0);  // the first sample of a flat-start group is kept
}

TEST(SampleSeries, DecimationKeepsEveryPeakAndTrough) {
    // A bouncing-ball-like signal: sharp minima at irregular times, one tall spike.
    SampleSeries s(256);
    double lowest_pushed = INFINITY, highest_pushed = -INFINITY, spike_time = 0;
    for (int i = 0; i < 100'000; ++i) {
        const double t = i * 1e-3;
        double v = std::abs(std::sin(3.1 * t)) * (1.0 + 0.1 * std::cos(0.7 * t)) - 0.5 * std::exp(-t);
        if (i == 31'337) {
            v = 42.0;
            spike_time = t;
        }
        lowest_pushed = std::min(lowest_pushed, v);
        highest_pushed = std::max(highest_pushed, v);
        s.push(t, v);
    }
    double lowest = INFINITY, highest = -INFINITY, highest_t = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
        lowest = std::min(lowest, s.values()[i]);
        if (s.values()[i] > highest) {
            highest = s.values()[i];
            highest_t = s.times()[i];
        }
    }
    EXPECT_EQ(lowest, lowest_pushed);
    EXPECT_EQ(highest, highest_pushed);
    EXPECT_EQ(highest_t, spike_time);  // the spike is kept at its own time, not moved
}

TEST(SampleSeries, IgnoresSamplesThatGoBackInTime) {
    SampleSeries s(16);
    s.push(1.0, 1.0);
    s.push(0.5, 2.0);
    s.push(1.0, 3.0);  // equal time is allowed (a bounce's before/after)
    ASSERT_EQ(s.size(), 2u);
    EXPECT_EQ(s.values()[1], 3.0);
}

TEST(PlotHistory, SpreadsTheSampleBudgetOverAllSeries) {
    PlotHistory h;
    h.reset(8, 16);
    std::size_t total_capacity = 0;
    for (const VariantTrack& v : h.variants) {
        for (const ParticleTrack& p : v.particles) total_capacity += p.height.capacity() + p.speed.capacity() + p.kinetic.capacity();
        // Every aggregate and ledger series, by name (a series left out of all() has no capacity set).
        const AggregateTrack& a = v.aggregate;
        for (const SampleSeries* s : {&a.height_mean, &a.height_min, &a.height_max, &a.speed_mean, &a.speed_min,
                                      &a.speed_max, &a.kinetic_total})
            total_capacity += s->capacity();
        const LedgerTrack& l = v.ledger;
        for (const SampleSeries* s :
             {&l.kinetic, &l.potential, &l.bounce, &l.friction, &l.drag, &l.wind_work, &l.residual})
            total_capacity += s->capacity();
    }
    EXPECT_LE(total_capacity, PlotHistory::sample_budget + 8 * 8 * 62);  // rounding up to multiples of 8
    h.reset(1, 1);  // few series: each can hold 100k points for smooth long plots
    EXPECT_GE(h.variants[0].particles[0].height.capacity(), 100'000u);
}

TEST(PlotHistory, AggregatesBeyondSixteenParticlesAndBoundsTheEventLog) {
    PlotHistory h;
    h.reset(1, 1000);
    EXPECT_TRUE(h.aggregated());
    EXPECT_EQ(h.variants[0].particles.size(), PlotHistory::max_tracked_particles);
    for (std::size_t i = 0; i < PlotHistory::max_logged_events + 5; ++i) {
        LoggedEvent e;
        e.event.t = static_cast<double>(i);
        h.log_event(e);
    }
    EXPECT_EQ(h.events.size(), PlotHistory::max_logged_events);
    EXPECT_EQ(h.events_dropped, 5u);
    EXPECT_EQ(h.events.front().event.t, 5.0);
}

}  // namespace
}  // namespace pl::ui
