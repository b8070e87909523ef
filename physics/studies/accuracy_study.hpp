// Work-precision study: one particle of one variant, run with each method over a ladder of step
// sizes (tolerances for adaptive Dormand-Prince), each compared at the end time with a reference
// solution: the closed form where the scene has one (no drag, or linear drag without wind, and no
// wall contact), otherwise adaptive Dormand-Prince at rtol = atol = 1e-12 with event location.
//
// Observed order: the least-squares slope of log(position error) against log(dt) over the
// fixed-step rows whose error is clearly above their error floor (order_floor_margin times it):
// below that the error measures the reference and round-off, not the method, and bends the
// slope. A row's floor (AccuracyRow::error_floor) is the reference's error plus the run's
// round-off:
//  * reference error (AccuracyReport::reference_error): 0 for a closed form; for Dormand-Prince,
//    a tenth of the distance between the reference and a second one at 10x its tolerance (its
//    global error grows about in proportion to the tolerance: Hairer, Norsett & Wanner, Solving
//    ODEs I, II.4, "tolerance proportionality");
//  * round-off: N eps (1 + |x_ref|) over the run's N steps, the worst case of one rounding of the
//    position per step in the same direction (a particle at terminal velocity adds nearly the same
//    increment to x every step, and the roundings do add up: 5e-9 m at |x| = 500 m, N = 5e5).
// With fewer than min_order_points such rows no order is reported (MethodOrder::too_few_points).
#pragma once

#include "physics/model/scene.hpp"

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace pl {

struct AccuracyOptions {
    std::vector<Method> methods;       // empty: all six
    std::vector<double> dts;           // empty: 5 values halving from 4x the variant's dt
    std::vector<double> tolerances;    // dopri5 rtol = atol; empty: 1e-3 ... 1e-9 (decades)
    double duration_s = 2.0;           // rounded up to a whole number of the largest dt
    std::size_t variant = 0;
    std::size_t particle = 0;
    // Run dopri5 over the dt ladder as a fixed-step method (IntegratorSettings::adaptive =
    // false) instead of over the tolerance ladder.
    bool dopri5_fixed_step = false;
    // Outer step of the adaptive runs (dopri5 over tolerances, and the reference); 0: the whole
    // duration in one outer step, so the error control alone sets the internal step size, unless
    // the reference reaches a wall: rest is decided per outer step (a rebound whose whole series of
    // bounces would end within the step rests), so then the variant's own dt.
    double adaptive_outer_dt_s = 0.0;
    double reference_tolerance = 1e-12;
    std::function<void(double fraction)> progress;  // called from the running thread
    const std::atomic<bool>* cancel = nullptr;
};

struct AccuracyRow {
    Method method = Method::semi_implicit_euler;
    bool adaptive = false;      // dopri5 with error control: `tolerance` is set, `dt` is the outer step
    double dt = 0.0;
    double tolerance = 0.0;
    std::uint64_t steps = 0;              // fixed steps, or accepted + rejected internal steps (adaptive)
    std::uint64_t force_evaluations = 0;  // including those of the time-of-impact searches
    double wall_seconds_per_sim_second = 0.0;
    double position_error = 0.0;  // |x - x_ref| at the end, m
    double error_floor = 0.0;     // m: the smallest position error this row can measure (file comment)
    double velocity_error = 0.0;  // |v - v_ref| at the end, m/s
    // max |t_bounce - t_bounce_ref| over impacts matched in order (same wall); empty if none.
    std::optional<double> bounce_time_error;
    std::size_t impacts = 0, impacts_matched = 0;
};

// A row's error counts for the order fit when it is at least this many times its error floor
// (the floor then changes its logarithm by at most log(1.1): a slope bias below 0.14 over a halving).
constexpr double order_floor_margin = 10.0;
// Fewest rows above the floor an order is fitted through: two points always lie on a line, a
// third shows whether the errors do.
constexpr std::size_t min_order_points = 3;

struct MethodOrder {
    Method method = Method::semi_implicit_euler;
    int expected = 1;               // method_order()
    std::optional<double> observed; // least-squares slope of log(position error) vs log(dt)
    std::size_t points = 0;         // rows used (errors clearly above the error floor)
    std::size_t rows = 0;           // rows of the series
    // Fewer than min_order_points rows above the floor: `observed` is empty, not a misleading slope.
    bool too_few_points = false;
    std::string note() const;  // "too few points above the floor (1 of 5, 3 needed)", or empty
};

struct AccuracyReport {
    std::vector<AccuracyRow> rows;
    std::vector<MethodOrder> orders;  // fixed-step series only
    std::string reference;            // how the reference was obtained
    double reference_error = 0.0;     // m: the reference's estimated error (file comment)
    std::size_t reference_impacts = 0;
    double duration_s = 0.0;          // the end time actually compared
    std::string variant_label;
    std::size_t particle = 0;
    bool cancelled = false;
    std::string error;  // bad options (names the option and the rule); rows empty then
};

AccuracyReport run_accuracy_study(const Scene& scene, const AccuracyOptions& options);

// Least-squares slope of log(y) against log(x) over the pairs with x, y > 0; empty if < 2.
std::optional<double> log_log_slope(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace pl
