// Model advisor: which force terms does this scene need, and why? For every variant the scene's
// own trajectories are run once per candidate term (advisor_terms.hpp: one table row per term,
// e.g. drag, each cheaper drag model against sphere_re, buoyancy, wind) and the verdicts come
// from the differences actually measured, metric by metric (landing time, impact speeds, time to
// rest, range, apex, landing point), each against its own tolerance, alongside the dimensionless
// numbers that explain them (Reynolds range, drag/weight ratio, Mach number, density ratio).
#pragma once

#include "physics/model/drag.hpp"
#include "physics/model/scene.hpp"
#include "physics/studies/collision_estimate.hpp"

#include <array>
#include <atomic>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace pl {

// What the advisor compares between two runs of the same particles (landing = first impact on a
// floor, a wall that gravity presses toward).
enum class AdviceMetric {
    landing_time,   // s, time of the first floor impact
    impact_speed,   // m/s, |v| just before each of the first advice_impacts floor impacts
    time_to_rest,   // s, when the particle comes to rest (velocity exactly zero on a wall) within the run
    range,          // m, horizontal (x-z) distance from the start to the landing point
    apex_height,    // m, highest centre height over the floor before landing
    landing_point,  // m, distance between the two landing points (or end points if it never landed)
};
inline constexpr std::size_t advice_metric_count = 6;
inline constexpr std::array<AdviceMetric, advice_metric_count> advice_metrics = {
    AdviceMetric::landing_time, AdviceMetric::impact_speed, AdviceMetric::time_to_rest,
    AdviceMetric::range,        AdviceMetric::apex_height,  AdviceMetric::landing_point};
// VariantAdvice::chaos: the starts are moved by chaos_nudge times the length tolerance (half: a
// particle that meets none lands that much further, within tolerance), and a difference up to
// chaos_factor times the nudge's is as likely chaos as a term's effect.
inline constexpr double chaos_nudge = 0.5;
inline constexpr double chaos_factor = 2.0;
// A mean shift counts as systematic past this many standard errors (a two-sided 0.3% chance of
// pure noise), from at least systematic_samples differences.
inline constexpr double systematic_errors = 3.0;
inline constexpr std::size_t systematic_samples = 10;
inline constexpr int advice_impacts = 3;  // impact speeds compared: the first three floor impacts
const char* to_string(AdviceMetric m);    // "landing time"
const char* json_key(AdviceMetric m);     // "landing_time_s"
const char* unit_of(AdviceMetric m);      // "s", "m/s", "m"

// Tolerance rule: a metric's difference d between two runs, for a particle whose baseline value
// is b, is beyond tolerance when |d| > max(absolute tolerance of the metric's unit, relative * |b|).
// The landing point has no baseline value (it is a distance between two points): absolute only.
// A term matters when any metric of any particle is beyond tolerance.
struct AdviceTolerances {
    double metres = 1e-3;             // range, apex height, landing point
    double seconds = 1e-3;            // landing time, time to rest
    double metres_per_second = 1e-3;  // impact speeds
    double relative = 0.0;            // fraction of the baseline value; 0: absolute tolerances only
    double absolute(AdviceMetric m) const;
    // The rule above: the largest |difference| within tolerance for a baseline value b.
    double limit(AdviceMetric m, double baseline) const;
};

struct AdviceOptions {
    double tolerance_m = 1e-3;    // AdviceTolerances::metres
    double tolerance_s = 1e-3;    // AdviceTolerances::seconds
    double tolerance_mps = 1e-3;  // AdviceTolerances::metres_per_second
    double relative_tolerance = 0.0;
    // Runs stop when every particle has come to rest (or was frozen), or at this time: the
    // bound on the time-to-rest wait (a particle that never rests is compared up to here).
    double max_duration_s = 20.0;
    std::function<void(double fraction)> progress;  // called from the running thread
    const std::atomic<bool>* cancel = nullptr;
    AdviceTolerances tolerances() const { return {tolerance_m, tolerance_s, tolerance_mps, relative_tolerance}; }
};

// One metric of one comparison, for the particle whose difference is furthest beyond (or
// closest to) its tolerance: the largest |difference| / tolerance over the particles.
struct MetricDelta {
    bool measured = false;     // some particle has the metric in both runs (or in one: at_least)
    double difference = 0.0;   // value - baseline (landing point: the distance, >= 0)
    double value = 0.0, baseline = 0.0;
    bool at_least = false;     // reached in one run only: the other's value is taken at the run's end, a bound
    bool beyond_tolerance = false;  // this particle or any other
    // Beyond tolerance, but not more than chaos_factor times what moving the starts changes
    // (VariantAdvice::chaos): as likely the scene's chaos as the term's own effect.
    bool within_chaos = false;
    // Over the particles (and impacts) that both runs measured, the signed differences' mean and
    // its standard error (sd / sqrt(samples)); not for the landing point, a distance.
    std::size_t samples = 0;
    double mean = 0.0, standard_error = 0.0;
    // Within the chaos particle by particle, yet the mean shift is beyond tolerance and beyond
    // chance (more than systematic_errors standard errors from 0): the term's own effect.
    bool systematic = false;
    std::size_t particle = 0;
    int impact = 0;            // impact_speed: which floor impact (1 = the first)
    std::optional<double> relative() const;  // difference / baseline (none for the landing point or b = 0)
};

// One row of the term table run on one variant (advisor_terms.hpp says how rows compare):
// toggle rows measure "term on" against "term off"; alternative rows a cheaper drag model
// against the reference (sphere_re with the variant's settings).
struct ModelRun {
    std::string term;               // the row's name, e.g. "buoyancy", "linear drag"
    bool alternative = false;       // false: a toggle row
    bool in_scene = false;          // the variant has the term on / uses this drag model
    std::string not_applicable;     // non-empty: not judged, and why (e.g. "no wind in this scene")
    // Settings of the simpler run: the term off (toggle rows) or the alternative model.
    DragModel model = DragModel::none;
    bool with_wind = true;
    bool buoyancy = false;
    std::array<MetricDelta, advice_metric_count> metrics{};
    bool matters = false;  // some metric beyond tolerance
    // Every metric beyond tolerance is within the scene's chaos (MetricDelta::within_chaos):
    // `matters` then means some of them is systematic.
    bool within_chaos = false;
    // Max over particles of |landing point difference| and |apex difference|, m (summary numbers
    // beside the metrics: the JSON's landing_difference_m and apex_difference_m).
    double landing_difference_m = 0.0;
    double apex_difference_m = 0.0;
    const MetricDelta& metric(AdviceMetric m) const { return metrics[static_cast<std::size_t>(m)]; }
};

struct VariantAdvice {
    std::string label;
    DragModel configured = DragModel::none;
    WindKind wind = WindKind::none;
    bool buoyancy = false;
    double re_min = 0.0, re_max = 0.0;   // over the reference trajectories
    double max_drag_to_weight = 0.0;     // max |F_drag| / (m |g|) over the reference trajectories
    double max_mach = 0.0;               // max |v - w| / 343 m/s (air at 15 C)
    // Per particle rho_air / rho_particle, rho_particle = m / (4/3 pi R^3): the buoyant fraction
    // of the weight (Archimedes).
    std::vector<double> density_ratio;
    std::vector<ModelRun> runs;          // one per table row, in table order
    // Kinetic-theory estimate of the collision rate over all the scene's particles (not only the
    // advice's first 100), over the collisions-off run's duration; and the recommendation.
    CollisionEstimate collisions;
    bool collisions_recommended = false;
    // With collisions on, trajectories can be chaotic: particles that meet amplify any difference
    // (a positive Lyapunov exponent), so a term that moves the particles by about the length
    // tolerance before they meet can change where each one ends by much more, as any change of
    // that size would. The scene is run again with every start moved by half the length
    // tolerance and compared with its own run (chaos: term "nudged starts"). Where that nudge moves a
    // metric beyond tolerance, a row's difference in it up to chaos_factor times the nudge's is
    // marked (MetricDelta::within_chaos), and the variant warns: compared particle by particle,
    // such a difference does not show the term's own effect. A row whose every difference beyond
    // tolerance is marked matters only if one of them shifts on average, beyond tolerance and
    // chance (MetricDelta::systematic: chaos scatters each particle, a term shifts them all).
    // The collisions row, the chaos's source rather than a small change within it, is not marked.
    bool chaos_measured = false;
    ModelRun chaos;
    // max over the trajectory of (sphere_re drag) / (Stokes drag) = Cd(Re) Re / 24
    double stokes_error_factor = 1.0;
    DragModel cheapest_adequate = DragModel::sphere_re;  // cheapest within tolerance of sphere_re
    double simulated_s = 0.0;            // longest run (stops when all rest, or at max duration)
    std::size_t distinct_runs = 0;       // simulations run: one per distinct model the rows compare
    std::vector<std::string> verdicts;   // one sentence per term
    std::vector<std::string> warnings;   // Mach > 0.3, models outside their validity range, ...
};

struct Advice {
    double tolerance_m = 0.0;
    AdviceTolerances tolerances;
    double max_duration_s = 0.0;
    std::vector<VariantAdvice> variants;
    std::size_t particles_used = 0, particles_total = 0;  // advice runs the first 100 particles
    bool cancelled = false;
};

Advice advise(const Scene& scene, const AdviceOptions& options);

// "landing time +0.62 s (+58%)", "landing point 3.1 mm", "time to rest >= +4.2 s (rests in one run only)".
std::string describe(AdviceMetric m, const MetricDelta& d);

}  // namespace pl
