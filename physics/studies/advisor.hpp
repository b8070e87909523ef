// Model advisor: which force terms does this scene need, and why? For every variant the scene's
// own trajectories are run with each drag model (none, linear/Stokes, quadratic, sphere_re, the
// richest and the reference) and, when there is wind, without it; the verdicts come from the
// differences actually measured (landing point, apex) against a stated tolerance, alongside the
// dimensionless numbers that explain them (Reynolds range, drag/weight ratio, Mach number).
#pragma once

#include "physics/model/drag.hpp"
#include "physics/model/scene.hpp"

#include <atomic>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace pl {

struct AdviceOptions {
    double tolerance_m = 1e-3;  // a term matters if it moves the landing point or apex by more
    double max_duration_s = 20.0;  // runs stop when every particle has landed, or at this time
    std::function<void(double fraction)> progress;  // called from the running thread
    const std::atomic<bool>* cancel = nullptr;
};

// Outcome of one drag model on the variant's particles (landing = first floor impact).
struct ModelRun {
    DragModel model = DragModel::none;
    bool with_wind = true;
    std::vector<std::optional<Vec3>> landing;  // per particle; empty if it never reached the floor
    std::vector<double> landing_time;
    std::vector<double> apex_height;           // highest centre height over the floor before landing
    // Differences to the reference run (sphere_re with the variant's wind), max over particles, m.
    double landing_difference_m = 0.0;
    double apex_difference_m = 0.0;
};

struct VariantAdvice {
    std::string label;
    DragModel configured = DragModel::none;
    WindKind wind = WindKind::none;
    double re_min = 0.0, re_max = 0.0;   // over the reference trajectories
    double max_drag_to_weight = 0.0;     // max |F_drag| / (m |g|) over the reference trajectories
    double max_mach = 0.0;               // max |v - w| / 343 m/s (air at 15 C)
    std::vector<ModelRun> runs;          // none, linear, quadratic, sphere_re, then without wind
    // max over the trajectory of (sphere_re drag) / (Stokes drag) = Cd(Re) Re / 24
    double stokes_error_factor = 1.0;
    DragModel cheapest_adequate = DragModel::sphere_re;  // cheapest within tolerance of sphere_re
    std::vector<std::string> verdicts;   // one sentence per term
    std::vector<std::string> warnings;   // Mach > 0.3, models outside their validity range, ...
};

struct Advice {
    double tolerance_m = 0.0;
    std::vector<VariantAdvice> variants;
    std::size_t particles_used = 0, particles_total = 0;  // advice runs the first 100 particles
    bool cancelled = false;
};

Advice advise(const Scene& scene, const AdviceOptions& options);

}  // namespace pl
