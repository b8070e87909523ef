// Comparison metrics of each variant (time of flight, apex, range, bounces, time to rest, energy
// lost, cost), measured from the state after every step, the event stream and, for the apex and
// the first impact, the step's own trajectory: a step in which a particle turns downwards or
// first meets a wall is replayed for that particle with a trace (physics/stepping/step_replay.hpp),
// which gives the highest point inside the step and the impact's located position, so both
// converge with the method's order rather than with the step (an apex sampled at step ends is off
// by up to dt / 2 in time). The other numbers can be recomputed from the CLI's trajectory and
// events CSV written with --every 1 (tests/cli/compare_matches_csv.sh does, and checks the apex
// and range against the step ends around them).
//
// Conventions: y is up; heights are measured from the floor (the room's lowest y), as in the
// trajectory CSV; "horizontal" means the x-z plane.
#pragma once

#include "physics/stepping/events.hpp"
#include "physics/model/scene.hpp"
#include "physics/stepping/simulation.hpp"
#include "physics/stepping/step_replay.hpp"

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace pl {

struct ParticleMetrics {
    // Time of flight: time of the first impact (a bounce or rest event on any wall).
    std::optional<double> first_impact_time;
    int first_impact_wall = -1;
    std::optional<double> first_impact_speed;  // |v| just before the first impact, m/s
    // Horizontal distance from the start to the first impact point: the impact's position as the
    // stepper located it on the step's own trajectory (StepTrace::impacts).
    std::optional<double> range_at_first_impact;
    // Highest centre height over the floor, at the start, at the step ends or inside a step on the
    // step's own trajectory (the vertex of the Euler/Verlet position polynomial, or where the
    // vertical velocity of RK4 re-run with a shorter step / Dormand-Prince's dense output crosses
    // zero), and when.
    double apex_height = 0.0;
    double apex_time = 0.0;
    double final_range = 0.0;  // horizontal distance from the start to the last position
    std::size_t bounces = 0;   // bounce events (rebounds); the impact that ends in rest is not one
    // When the particle ends the run at rest (resting on a wall, velocity exactly zero): the time
    // of the last event that left it with zero velocity (rest with speed_out 0, or stop).
    std::optional<double> time_to_rest;
    // Ledger at the end, J.
    double lost_drag = 0.0, lost_bounce = 0.0, lost_friction = 0.0, wind_work = 0.0;
};

struct VariantMetrics {
    std::string label;
    std::vector<ParticleMetrics> particles;
    // First time every particle is stopped (the latest time_to_rest), when all end at rest.
    std::optional<double> all_at_rest_time;
    // Totals over all particles, J.
    double lost_drag = 0.0, lost_bounce = 0.0, lost_friction = 0.0, wind_work = 0.0;
    double energy_residual = 0.0;  // E0 + wind work - (KE + PE + dissipated): the integrator's error
    double simulated_seconds = 0.0;
    std::uint64_t steps = 0;
    double physics_seconds = 0.0;  // wall time spent stepping this variant
    // Cost: physics wall time per simulated second (0 before the first step).
    double cost() const { return simulated_seconds > 0.0 ? physics_seconds / simulated_seconds : 0.0; }
};

// Live accumulation for one variant's Simulation. Call start_metrics once at t = 0, then
// observe_step after every step of that simulation, passing the events that step produced
// (drain them once and share them with other consumers) and the wall time the step took.
struct MetricsTracker {
    std::vector<Vec3> start_position;
    std::vector<StepStart> prev;  // state before the latest step (what a replay starts from)
    double prev_time = 0.0;
    std::uint64_t prev_steps = 0;  // steps taken then: a replay reproduces one step only
    double floor_y = 0.0;
    std::vector<ParticleMetrics> particles;
    std::vector<std::optional<double>> stopped_since;  // time of the last event that left v == 0
    double physics_seconds = 0.0;
};

MetricsTracker start_metrics(const Simulation& sim);
void observe_step(MetricsTracker& tracker, const Simulation& sim, const std::vector<Event>& new_events,
                  double physics_seconds);
VariantMetrics metrics_of(const MetricsTracker& tracker, const Simulation& sim);

// Differences of one variant to the baseline for one particle (value - baseline value); an
// optional is empty when either side has no value.
struct MetricsDifference {
    std::optional<double> first_impact_time, range_at_first_impact, time_to_rest, all_at_rest_time;
    double apex_height = 0.0, final_range = 0.0;
    long long bounces = 0;
    double lost_drag = 0.0, lost_bounce = 0.0, lost_friction = 0.0;
    double cost = 0.0;
};
MetricsDifference metrics_difference(const VariantMetrics& value, const VariantMetrics& baseline,
                                     std::size_t particle);

// Lockstep schedule (the rule Experiment::step_base uses): steps `sim` while its next step ends
// at or before the common time `t`. Returns the number of steps taken.
std::uint64_t catch_up(Simulation& sim, double t);

// Number of base steps for `duration` and the check that every variant's dt divides it, so each
// variant's final state is at exactly t = duration. Empty error: ok.
struct DurationPlan {
    std::uint64_t base_steps = 0;
    double base_dt = 0.0;
    std::string error;  // names the variant whose dt does not divide the duration
};
DurationPlan plan_duration(const Scene& scene, double duration_s);

struct CompareOptions {
    double duration_s = 5.0;
    std::function<void(double fraction)> progress;  // called from the running thread
    const std::atomic<bool>* cancel = nullptr;      // set to stop early (result.cancelled)
    // Threads each variant's simulation uses; 0: all hardware threads. Studies that run many
    // scenes at once (sweep) give 1 and run a scene per core instead.
    int threads = 0;
};

struct Comparison {
    std::vector<VariantMetrics> variants;
    double duration_s = 0.0;
    bool cancelled = false;
    std::string error;  // bad duration (see plan_duration); variants empty then
};

// Runs every variant of the scene in lockstep to `duration_s` and measures it.
Comparison run_comparison(const Scene& scene, const CompareOptions& options);

}  // namespace pl
