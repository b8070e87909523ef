// Stability study: the classification agrees with the known limits and catches the failures
// it names.
#include "physics/studies/stability_study.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace pl {
namespace {

StabilityCase drag_case(Method method, double k, double hk) {
    StabilityCase c;
    c.method = method;
    c.stiffness = k;
    c.dt = hk / k;
    c.speed = 5.0;
    c.restitution = 0.5;
    c.radius_fraction = 0.05;
    return c;
}

TEST(StabilityStudy, SemiImplicitEulerWithLinearDragIsStableBelowHk2AndNotAbove) {
    const StabilityBase base = default_stability_base();
    for (double k : {100.0, 1000.0}) {
        const StabilityCell below = classify_stability(base, drag_case(Method::semi_implicit_euler, k, 1.8));
        EXPECT_EQ(below.outcome, StabilityOutcome::stable) << "k = " << k << ": " << below.detail;
        const StabilityCell above = classify_stability(base, drag_case(Method::semi_implicit_euler, k, 2.2));
        EXPECT_TRUE(above.outcome == StabilityOutcome::energy_growth || above.outcome == StabilityOutcome::nan)
            << "k = " << k << ": " << to_string(above.outcome);
    }
}

TEST(StabilityStudy, Rk4LimitIsAbout2Point785AndTheExponentialStepHasNone) {
    const StabilityBase base = default_stability_base();
    EXPECT_EQ(classify_stability(base, drag_case(Method::rk4, 100.0, 2.6)).outcome, StabilityOutcome::stable);
    EXPECT_NE(classify_stability(base, drag_case(Method::rk4, 100.0, 3.0)).outcome, StabilityOutcome::stable);
    const StabilityCell stiff = classify_stability(base, drag_case(Method::exponential, 1e4, 100.0));
    EXPECT_EQ(stiff.outcome, StabilityOutcome::stable) << stiff.detail;
}

TEST(StabilityStudy, ExplicitEulerGainsEnergyWithoutDrag) {
    StabilityCase c;
    c.method = Method::explicit_euler;
    c.dt = 0.02;
    c.restitution = 1.0;
    const StabilityCell cell = classify_stability(default_stability_base(), c);
    EXPECT_EQ(cell.outcome, StabilityOutcome::energy_growth) << cell.detail;
    EXPECT_GT(cell.max_energy_ratio, 1.0 + stability_energy_tolerance);
    c.method = Method::velocity_verlet;  // exact under constant gravity
    EXPECT_EQ(classify_stability(default_stability_base(), c).outcome, StabilityOutcome::stable);
}

TEST(StabilityStudy, FastAndLargeParticlesStayInTheRoom) {
    // 1 km/s in a 2 m room at dt = 0.01 (5 wall crossings per step), and a radius of 49% of the room.
    StabilityCase fast;
    fast.method = Method::semi_implicit_euler;
    fast.dt = 0.01;
    fast.speed = 1000.0;
    fast.restitution = 1.0;
    const StabilityCell a = classify_stability(default_stability_base(), fast);
    EXPECT_NE(a.outcome, StabilityOutcome::tunnelled) << a.detail;
    EXPECT_NE(a.outcome, StabilityOutcome::escaped) << a.detail;
    StabilityCase big = fast;
    big.speed = 10.0;
    big.radius_fraction = 0.49;
    const StabilityCell b = classify_stability(default_stability_base(), big);
    EXPECT_EQ(b.outcome, StabilityOutcome::stable) << b.detail;
}

TEST(StabilityStudy, ADropSettlesWithinTheRestBound) {
    StabilityCase drop;
    drop.method = Method::semi_implicit_euler;
    drop.dt = 1e-3;
    drop.speed = 0.0;
    drop.restitution = 0.5;
    const StabilityCell cell = classify_stability(default_stability_base(), drop);
    EXPECT_TRUE(cell.jitter_checked);
    EXPECT_EQ(cell.outcome, StabilityOutcome::stable) << cell.detail;
}

TEST(StabilityStudy, MeasuredLimitSitsBesideTheTheoreticalOne) {
    StabilityOptions o;
    o.threads = 2;
    const std::vector<double> dts = {0.005, 0.01, 0.015, 0.018, 0.022, 0.03};
    const std::vector<StabilityCell> cells =
        stability_map(default_stability_base(), Method::semi_implicit_euler, dts, {0.0, 100.0}, 5.0, 0.5, 0.05, o);
    ASSERT_EQ(cells.size(), dts.size() * 2);
    EXPECT_EQ(cells[1].c.dt, 0.005);  // dts outer, k inner
    EXPECT_EQ(cells[1].c.stiffness, 100.0);
    const std::vector<StabilityLimit> limits = stability_limits(cells);
    ASSERT_EQ(limits.size(), 2u);
    const StabilityLimit& drag = limits[1];
    EXPECT_EQ(drag.stiffness, 100.0);
    EXPECT_DOUBLE_EQ(drag.theoretical_dt, 0.02);
    ASSERT_TRUE(drag.measured_dt && drag.first_unstable_dt);
    EXPECT_EQ(*drag.measured_dt, 0.018);
    EXPECT_EQ(*drag.first_unstable_dt, 0.022);
    EXPECT_EQ(limits[0].theoretical_dt, std::numeric_limits<double>::infinity());

    // The same cells whatever the thread count.
    o.threads = 1;
    const std::vector<StabilityCell> single =
        stability_map(default_stability_base(), Method::semi_implicit_euler, dts, {0.0, 100.0}, 5.0, 0.5, 0.05, o);
    for (std::size_t i = 0; i < cells.size(); ++i) {
        EXPECT_EQ(cells[i].outcome, single[i].outcome);
        EXPECT_EQ(cells[i].max_energy_ratio, single[i].max_energy_ratio);
    }
}

TEST(StabilityStudy, QuickGridCoversEveryMethodAndCanBeCancelled) {
    StabilityOptions o;
    o.grid = default_stability_grid(true);
    std::atomic<bool> cancel{true};
    o.cancel = &cancel;
    const StabilityReport cancelled = run_stability_study(default_stability_base(), o);
    EXPECT_TRUE(cancelled.cancelled);
    EXPECT_TRUE(cancelled.map_cells.empty());
    const StabilityGrid full = default_stability_grid(false);
    EXPECT_EQ(full.dts.front(), 1e-5);
    EXPECT_EQ(full.dts.back(), 0.5);
    EXPECT_EQ(full.stiffnesses.back(), 1e4);
    EXPECT_EQ(full.speeds.back(), 1e3);
    EXPECT_EQ(full.radius_fractions.back(), 0.49);
    EXPECT_EQ(full.methods.size(), 6u);
}

}  // namespace
}  // namespace pl
