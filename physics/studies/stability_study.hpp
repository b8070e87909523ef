// Stability at the extremes: a grid over time step, linear-drag stiffness k (b = k m), launch
// speed, restitution, particle radius and method; each cell is one particle launched from the
// room's centre and classified by what happened to it. A collision slice throws two balls at
// each other instead, over time step, speed, restitution, radius ratio and mass ratio.
#pragma once

#include "physics/collide/collision_pass.hpp"
#include "physics/model/scene.hpp"

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace pl {

class Simulation;

enum class StabilityOutcome : std::uint8_t {
    stable,
    energy_growth,  // KE + PE rose above E0 by more than energy_tolerance (no energy source here)
    nan,            // the state became non-finite (the particle was frozen)
    escaped,        // the sphere overlapped a wall (centre beyond its contact plane)
    jitter,         // e < 1 but still bouncing on the floor after the time-to-rest bound (or
                    // explicit Euler's rest trap seen before it, Warning no_rest)
    tunnelled,      // the centre passed through a wall (outside the room); of a pair, one ball
                    // passed through the other
    overlap,        // a pair: a step left the two balls deeper in each other than
                    // collision_overlap_limit of their contact distance
};
constexpr std::size_t stability_outcome_count = static_cast<std::size_t>(StabilityOutcome::overlap) + 1;
const char* to_string(StabilityOutcome o);

// One cell of the grid.
struct StabilityCase {
    Method method = Method::semi_implicit_euler;
    double dt = 0.01;
    double stiffness = 0.0;        // k, 1/s: linear drag with b = k m
    double speed = 5.0;            // launch speed, m/s
    double restitution = 0.5;
    double radius_fraction = 0.05; // radius / smallest room size (< 0.5); of a pair, ball 0's
    // A pair (collision slice) when > 0: ball 1's radius and mass over ball 0's.
    double pair_radius_ratio = 0.0;
    double pair_mass_ratio = 1.0;
    bool pair() const { return pair_radius_ratio > 0.0; }
};

struct StabilityCell {
    StabilityCase c;
    StabilityOutcome outcome = StabilityOutcome::stable;
    std::uint64_t steps = 0;
    double simulated_s = 0.0;
    double max_energy_ratio = 0.0;  // max (KE + PE) / E0 over the run
    bool jitter_checked = false;    // the run lasted past the time-to-rest bound (e < 1)
    double max_overlap = 0.0;       // a pair: deepest overlap at a step's end, share of the contact distance
    bool collision_warned = false;  // a pair: the engine raised collision_overlap or collision_crossing
    std::string detail;             // what was seen, e.g. "t = 0.42 s: KE + PE = 3.1 E0"
};

// How long each cell runs: min(max_steps dt, max_duration_s), but at least min_steps steps, and
// past the time-to-rest bound where that takes at most rest_steps_factor max_steps steps.
struct StabilityRunLimits {
    static constexpr std::uint64_t rest_steps_factor = 25;
    std::uint64_t max_steps = 4000;
    std::uint64_t min_steps = 50;
    double max_duration_s = 5.0;
};

// The grid is a union of slices rather than the full product:
//  * the dt x k map for every method, at map_speed / map_restitution / map_radius_fraction;
//  * the dt x speed x restitution x radius sweep for every method, at k = 0 and at k = sweep_k;
//  * the collision slice: pairs over dt x speed x restitution x radius ratio x mass ratio for
//    every method (ball 0 of radius pair_radius_fraction of the room, friction the walls').
struct StabilityGrid {
    std::vector<Method> methods;
    std::vector<double> dts, stiffnesses;                       // map axes
    double map_speed = 5.0, map_restitution = 0.5, map_radius_fraction = 0.05;
    std::vector<double> sweep_dts, speeds, restitutions, radius_fractions;
    std::vector<double> sweep_stiffnesses;
    std::vector<double> pair_dts, pair_speeds, pair_restitutions, pair_radius_ratios, pair_mass_ratios;
    double pair_radius_fraction = 0.01;
    StabilityRunLimits limits;
};
StabilityGrid default_stability_grid(bool quick);

// Tolerances used by the classification.
constexpr double stability_energy_tolerance = 0.01;  // relative to E0 (E0 >= m |g| 1 mm)
// The depth past which a pair's overlap is an outcome of its own: the engine's collision_overlap
// warning limit.
constexpr double collision_overlap_limit = collide::CollisionPass::warn_overlap;

// The scene provides the room, gravity, contact friction / rest speed and the particle's mass
// (particle 0); launch position is the room's centre, the direction a fixed oblique one.
struct StabilityBase {
    Room room;
    Vec3 gravity{0.0, -9.81, 0.0};
    ContactSettings contact;
    double mass = 0.057;
};
StabilityBase stability_base(const Scene& scene);
StabilityBase default_stability_base();  // the seed's 2 m cube room

// One cell: a single particle, or a pair (c.pair(): collision_stability.cpp).
StabilityCell classify_stability(const StabilityBase& base, const StabilityCase& c,
                                 const StabilityRunLimits& limits = {});
StabilityCell classify_pair(const StabilityBase& base, const StabilityCase& c, const StabilityRunLimits& limits = {});

// Shared by the classifiers. The model of a cell: the base's room, gravity and contact, the
// cell's restitution (at the walls), method and dt; no drag, no collisions.
Model stability_model(const StabilityBase& base, const StabilityCase& c, const char* label);
// The steps a cell runs before any lengthening for the rest bound:
// ceil(max_duration_s / dt) within [min_steps, max_steps].
std::uint64_t stability_steps(const StabilityCase& c, const StabilityRunLimits& limits);
// A sphere at `x` against the room's walls at time `t`: tunnelled (its centre beyond a wall) or
// escaped (the sphere into one), by more than round-off of the room's size; `what` names the
// particle in the detail. Nothing when it is inside.
struct WallOutcome {
    StabilityOutcome outcome;
    std::string detail;
};
std::optional<WallOutcome> wall_outcome(const Room& room, const Vec3& x, double radius, double t, const std::string& what);
// Keeps the largest energy / e0 in `cell`; when `energy` exceeds e0 by stability_energy_tolerance
// of `scale`, what was seen.
std::optional<std::string> energy_grown(StabilityCell& cell, double energy, double e0, double scale, double t);
// The cell as it ended: its outcome, what was seen, and how far `sim` ran.
StabilityCell finish_cell(StabilityCell cell, const Simulation& sim, StabilityOutcome o, std::string detail);

struct StabilityLimit {
    Method method = Method::semi_implicit_euler;
    double stiffness = 0.0;
    double theoretical_dt = 0.0;            // method_stability_limit / k (+inf if none)
    std::optional<double> measured_dt;      // largest grid dt with it and every smaller dt stable
    std::optional<double> first_unstable_dt;
};

struct StabilityOptions {
    StabilityGrid grid = default_stability_grid(false);
    unsigned threads = 0;  // 0: hardware concurrency
    std::function<void(double fraction)> progress;  // called from a worker thread
    const std::atomic<bool>* cancel = nullptr;
};

struct StabilityReport {
    std::vector<StabilityCell> map_cells;    // method x dt x k
    std::vector<StabilityCell> sweep_cells;  // method x k x dt x speed x restitution x radius
    std::vector<StabilityCell> pair_cells;   // method x dt x speed x restitution x radius ratio x mass ratio
    std::vector<StabilityLimit> limits;      // per method and k of the map
    bool cancelled = false;
};

StabilityReport run_stability_study(const StabilityBase& base, const StabilityOptions& options);

// The dt x k map for one method (what the GUI draws), cells in row-major order: dts outer,
// stiffnesses inner.
std::vector<StabilityCell> stability_map(const StabilityBase& base, Method method, const std::vector<double>& dts,
                                         const std::vector<double>& stiffnesses, double speed, double restitution,
                                         double radius_fraction, const StabilityOptions& options);
// The launch direction of every cell (fixed, oblique: it reaches the floor and side walls).
Vec3 stability_launch_direction();

// Per method and k: the theoretical limit beside the measured one, from the map's cells.
std::vector<StabilityLimit> stability_limits(const std::vector<StabilityCell>& map_cells);

}  // namespace pl
