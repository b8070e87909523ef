// Work-precision study: one particle of one variant, run with each method over a ladder of step
// sizes (tolerances for adaptive Dormand-Prince), each compared at the end time with a reference
// solution: the closed form where the scene has one (no drag, or linear drag without wind, and no
// wall contact), otherwise adaptive Dormand-Prince at rtol = atol = 1e-12 with event location.
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
    // duration in one outer step, so the error control alone sets the internal step size.
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
    double velocity_error = 0.0;  // |v - v_ref| at the end, m/s
    // max |t_bounce - t_bounce_ref| over impacts matched in order (same wall); empty if none.
    std::optional<double> bounce_time_error;
    std::size_t impacts = 0, impacts_matched = 0;
};

struct MethodOrder {
    Method method = Method::semi_implicit_euler;
    int expected = 1;               // method_order()
    std::optional<double> observed; // least-squares slope of log(position error) vs log(dt)
    std::size_t points = 0;         // rows used (errors above the reference's accuracy floor)
};

struct AccuracyReport {
    std::vector<AccuracyRow> rows;
    std::vector<MethodOrder> orders;  // fixed-step series only
    std::string reference;            // how the reference was obtained
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
