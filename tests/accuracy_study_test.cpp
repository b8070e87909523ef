// The work-precision study: observed orders on a smooth drag trajectory, the closed-form
// reference, bounce-time errors, and option errors.
#include "physics/studies/accuracy_study.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace pl {
namespace {

// A light ball (2.7 g, r = 20 mm) thrown at 20 m/s with quadratic drag in a room too big to
// reach: drag peaks near 5x its weight, so the trajectory is strongly nonlinear yet smooth.
Scene smooth_drag_scene() {
    Scene s;
    s.room.center = {0, 0, 0};
    s.room.size = Vec3(1e4);
    s.drag.model = DragModel::quadratic;
    s.integrator.dt = 0.01;
    s.particles = {{{0, 0, 0}, {14, 14, 3}, 0.0027, 0.02}};
    return s;
}

double order_of(const AccuracyReport& r, Method m) {
    for (const MethodOrder& o : r.orders)
        if (o.method == m && o.observed) return *o.observed;
    ADD_FAILURE() << "no observed order for " << to_string(m);
    return 0.0;
}

TEST(AccuracyStudy, ObservedOrdersOnASmoothQuadraticDragTrajectory) {
    const Scene scene = smooth_drag_scene();
    struct Case {
        Method method;
        std::vector<double> dts;
        double expected;
    };
    const std::vector<Case> cases = {
        {Method::explicit_euler, {0.004, 0.002, 0.001, 0.0005}, 1.0},
        {Method::semi_implicit_euler, {0.004, 0.002, 0.001, 0.0005}, 1.0},
        {Method::velocity_verlet, {0.008, 0.004, 0.002, 0.001}, 2.0},
        {Method::rk4, {0.04, 0.02, 0.01, 0.005}, 4.0},
    };
    for (const Case& c : cases) {
        AccuracyOptions o;
        o.methods = {c.method};
        o.dts = c.dts;
        o.duration_s = 1.0;
        o.dopri5_fixed_step = true;
        const AccuracyReport r = run_accuracy_study(scene, o);
        ASSERT_TRUE(r.error.empty()) << r.error;
        EXPECT_EQ(r.reference_impacts, 0u);
        EXPECT_NE(r.reference.find("dopri5"), std::string::npos) << r.reference;
        ASSERT_EQ(r.rows.size(), c.dts.size());
        for (const AccuracyRow& row : r.rows) EXPECT_FALSE(row.adaptive);
        EXPECT_NEAR(order_of(r, c.method), c.expected, 0.2) << to_string(c.method);
        EXPECT_EQ(r.orders.front().points, c.dts.size()) << to_string(c.method) << ": errors hit the reference floor";
        // Cost grows as dt shrinks.
        EXPECT_GT(r.rows.back().force_evaluations, r.rows.front().force_evaluations);
    }
}

TEST(AccuracyStudy, DormandPrinceAtFixedStepIsFifthOrder) {
    // Measured against the linear-drag closed form (k = 1/s), whose error floor is round-off.
    // On the quadratic-drag scene above its slope reads about 7 over every step size whose error
    // stays above the 1e-12 reference's floor: DP5's fifth-order error constants are so small
    // (they were minimised by design) that higher-order terms dominate there.
    Scene scene = smooth_drag_scene();
    scene.drag.model = DragModel::linear;
    scene.drag.linear_b = 0.01;
    scene.particles[0].mass = 0.01;
    AccuracyOptions o;
    o.methods = {Method::dopri5};
    o.dopri5_fixed_step = true;
    o.dts = {0.2, 0.1, 0.05, 0.025};
    o.duration_s = 2.0;
    const AccuracyReport r = run_accuracy_study(scene, o);
    ASSERT_TRUE(r.error.empty()) << r.error;
    EXPECT_NE(r.reference.find("closed form (linear drag"), std::string::npos) << r.reference;
    EXPECT_NEAR(order_of(r, Method::dopri5), 5.0, 0.2);
    EXPECT_EQ(r.orders.front().points, 4u);
}

TEST(AccuracyStudy, AdaptiveMethodMeetsItsToleranceAgainstTheLinearDragClosedForm) {
    Scene scene = smooth_drag_scene();
    scene.drag.model = DragModel::linear;
    scene.drag.linear_b = 0.01;  // k = b / m = 3.7 1/s
    AccuracyOptions o;
    o.methods = {Method::dopri5};
    o.tolerances = {1e-4, 1e-6, 1e-8};
    o.duration_s = 2.0;
    const AccuracyReport r = run_accuracy_study(scene, o);
    ASSERT_TRUE(r.error.empty()) << r.error;
    EXPECT_NE(r.reference.find("closed form (linear drag"), std::string::npos) << r.reference;
    ASSERT_EQ(r.rows.size(), 3u);
    for (const AccuracyRow& row : r.rows) {
        EXPECT_TRUE(row.adaptive);
        // Local error per step is held below tol (1 + |y|); the global error stays within a
        // small multiple of it over this 2 s run (|x| ~ 10 m).
        EXPECT_LT(row.position_error, 100 * row.tolerance) << "tol " << row.tolerance;
        EXPECT_GT(row.steps, 0u);
    }
    EXPECT_GT(r.rows[0].position_error, r.rows[2].position_error);
    EXPECT_LT(r.rows[0].force_evaluations, r.rows[2].force_evaluations);
    EXPECT_TRUE(r.orders.empty());  // no fixed-step series was run
}

TEST(AccuracyStudy, FreeFlightUsesTheClosedFormAndSecondOrderMethodsAreExact) {
    Scene scene = smooth_drag_scene();
    scene.drag.model = DragModel::none;
    AccuracyOptions o;
    o.methods = {Method::velocity_verlet, Method::semi_implicit_euler};
    o.duration_s = 1.0;
    const AccuracyReport r = run_accuracy_study(scene, o);
    ASSERT_TRUE(r.error.empty()) << r.error;
    EXPECT_NE(r.reference.find("closed form (free flight"), std::string::npos);
    ASSERT_EQ(r.rows.size(), 10u);  // default ladder: 5 step sizes per method
    EXPECT_DOUBLE_EQ(r.rows[0].dt, 0.04);
    EXPECT_DOUBLE_EQ(r.rows[4].dt, 0.0025);
    for (int i = 0; i < 5; ++i) EXPECT_LT(r.rows[i].position_error, 1e-12);  // Verlet: exact under constant g
    EXPECT_NEAR(order_of(r, Method::semi_implicit_euler), 1.0, 0.05);
}

TEST(AccuracyStudy, BounceTimeErrorsShrinkWithTheStep) {
    Scene scene;
    scene.room.center = {0, 0, 0};
    scene.room.size = {4, 4, 4};
    scene.contact.restitution = 0.8;
    scene.contact.friction = 0.0;
    scene.particles = {{{0, 1.0, 0}, {0, 0, 0}, 0.1, 0.05}};
    scene.integrator.dt = 0.002;
    AccuracyOptions o;
    o.methods = {Method::semi_implicit_euler, Method::rk4};
    o.duration_s = 4.0;  // impacts near 0.78, 2.02, 3.01 and 3.80 s
    const AccuracyReport r = run_accuracy_study(scene, o);
    ASSERT_TRUE(r.error.empty()) << r.error;
    EXPECT_GE(r.reference_impacts, 3u);
    std::vector<double> dts, errors;
    for (const AccuracyRow& row : r.rows) {
        ASSERT_TRUE(row.bounce_time_error) << to_string(row.method) << " dt " << row.dt;
        EXPECT_EQ(row.impacts_matched, std::min(row.impacts, r.reference_impacts));
        if (row.method == Method::semi_implicit_euler) {
            dts.push_back(row.dt);
            errors.push_back(*row.bounce_time_error);
        }
    }
    const std::optional<double> slope = log_log_slope(dts, errors);
    ASSERT_TRUE(slope);
    EXPECT_NEAR(*slope, 1.0, 0.3);  // time of impact located on the step's own trajectory: first order
    // RK4 is exact for constant gravity: bounce times to the root search's precision.
    for (const AccuracyRow& row : r.rows) {
        if (row.method == Method::rk4) {
            EXPECT_LT(*row.bounce_time_error, 1e-9);
        }
    }
}

TEST(AccuracyStudy, TheReferenceBouncesAsOftenAsTheMethodsOverALongRun) {
    // A ball bouncing to rest in a 2 m room over 8 s. The reference's rest test works per outer
    // step (a rebound whose whole series of bounces would end within the step rests): with the
    // whole run as one outer step it rested at its third impact while RK4 bounced 20 times.
    Scene scene;
    scene.room.size = {2, 2, 2};
    scene.contact.restitution = 0.8;
    scene.contact.friction = 0.0;
    scene.particles = {{{0, 0.5, 0}, {0.3, 0, 0}, 0.1, 0.05}};
    scene.integrator.dt = 0.002;
    AccuracyOptions o;
    o.methods = {Method::rk4};
    o.duration_s = 8.0;
    const AccuracyReport r = run_accuracy_study(scene, o);
    ASSERT_TRUE(r.error.empty()) << r.error;
    EXPECT_GE(r.reference_impacts, 15u);
    for (const AccuracyRow& row : r.rows) {
        EXPECT_EQ(row.impacts, r.reference_impacts) << "dt " << row.dt;
        ASSERT_TRUE(row.bounce_time_error);
        EXPECT_LT(*row.bounce_time_error, 1e-6) << "dt " << row.dt;  // RK4 is exact for constant gravity
        EXPECT_LT(row.position_error, 1e-6) << "dt " << row.dt;
    }
}

TEST(AccuracyStudy, RK4OrderIsFittedOnlyAboveTheReferencesFloor) {
    // A looser Dormand-Prince reference (1e-9): RK4's errors reach its error (about 3e-10 m here)
    // at dt = 2.5 ms. Fitted through every row the slope bends towards 0; the floor is measured
    // (a second reference at 10x the tolerance) and the rows near it are left out.
    const Scene scene = smooth_drag_scene();
    AccuracyOptions o;
    o.methods = {Method::rk4};
    o.dts = {0.04, 0.02, 0.01, 0.005, 0.0025, 0.00125};
    o.duration_s = 1.0;
    o.reference_tolerance = 1e-9;
    const AccuracyReport r = run_accuracy_study(scene, o);
    ASSERT_TRUE(r.error.empty()) << r.error;
    EXPECT_GT(r.reference_error, 1e-11);
    EXPECT_LT(r.reference_error, 1e-8);
    ASSERT_EQ(r.orders.size(), 1u);
    const MethodOrder& order = r.orders.front();
    EXPECT_NEAR(order_of(r, Method::rk4), 4.0, 0.2);
    EXPECT_GE(order.points, min_order_points);
    EXPECT_LT(order.points, order.rows) << "the finest rows are at the floor";
    EXPECT_FALSE(order.too_few_points);
    EXPECT_TRUE(order.note().empty());
    std::vector<double> dts, errors;  // every row: what the floor keeps out
    for (const AccuracyRow& row : r.rows) {
        dts.push_back(row.dt);
        errors.push_back(row.position_error);
        EXPECT_GT(row.error_floor, r.reference_error);  // plus the run's round-off
    }
    EXPECT_LT(*log_log_slope(dts, errors), 3.6);
}

TEST(AccuracyStudy, TooFewPointsAboveTheFloorGiveNoOrder) {
    // Linear drag (k = 1/s) for 50 s: the transient has died out, RK4's end-point errors are
    // round-off, growing with the number of steps (9e-10 m at dt = 2e-4 s, 5e-9 m at 1e-4 s,
    // |x| = 500 m). A slope through them (-2.6 here) is no order of the method.
    Scene scene = smooth_drag_scene();
    scene.drag.model = DragModel::linear;
    scene.drag.linear_b = 0.01;
    scene.particles[0].mass = 0.01;
    AccuracyOptions o;
    o.methods = {Method::rk4};
    o.dts = {0.2, 0.1, 0.05, 0.025, 2e-4, 1e-4};
    o.duration_s = 50.0;
    const AccuracyReport r = run_accuracy_study(scene, o);
    ASSERT_TRUE(r.error.empty()) << r.error;
    EXPECT_NE(r.reference.find("closed form (linear drag"), std::string::npos) << r.reference;
    ASSERT_EQ(r.orders.size(), 1u);
    const MethodOrder& order = r.orders.front();
    EXPECT_FALSE(order.observed) << *order.observed;
    EXPECT_TRUE(order.too_few_points);
    EXPECT_LT(order.points, min_order_points);
    EXPECT_EQ(order.rows, 6u);
    EXPECT_NE(order.note().find("too few points above the floor"), std::string::npos) << order.note();
}

TEST(AccuracyStudy, LogLogSlopeOfAPowerLaw) {
    const std::vector<double> x = {0.1, 0.2, 0.4, 0.8};
    std::vector<double> y;
    for (double v : x) y.push_back(3.0 * std::pow(v, 2.5));
    ASSERT_TRUE(log_log_slope(x, y));
    EXPECT_NEAR(*log_log_slope(x, y), 2.5, 1e-12);
    EXPECT_FALSE(log_log_slope({0.1}, {1.0}));
    EXPECT_FALSE(log_log_slope({0.1, 0.2}, {0.0, 0.0}));  // zero errors carry no slope
}

TEST(AccuracyStudy, BadOptionsNameTheOptionAndTheRule) {
    const Scene scene = smooth_drag_scene();
    AccuracyOptions o;
    o.dts = {0.004, 0.003};
    EXPECT_NE(run_accuracy_study(scene, o).error.find("--dt"), std::string::npos);
    o = {};
    o.variant = 3;
    EXPECT_NE(run_accuracy_study(scene, o).error.find("--variant"), std::string::npos);
    o = {};
    o.particle = 1;
    EXPECT_NE(run_accuracy_study(scene, o).error.find("--particle"), std::string::npos);
    o = {};
    o.tolerances = {2.0};
    EXPECT_NE(run_accuracy_study(scene, o).error.find("--tol"), std::string::npos);
}

}  // namespace
}  // namespace pl
