// What a simulation warns about, once per particle and kind. A big scene can raise a warning
// for most of its particles, so a warning keeps only the number it reports (24 bytes); its text
// is made when something shows it.
#pragma once

#include "physics/model/scene.hpp"

#include <cstddef>
#include <cstdint>
#include <string>

namespace pl {

enum class WarningKind : std::uint8_t {
    drag_validity,  // Re outside the drag model's validity range
    stability,      // dt * drag stiffness beyond the method's limit
    frozen,         // state became non-finite
    mach,           // relative speed above Mach 0.3: compressibility not modelled
    runaway,        // speed beyond the speed of light (a finite blow-up): frozen
    impact_cap,     // more wall impacts in one step than max_impacts_per_step: frozen
    no_rest,        // explicit Euler at this dt cannot come to rest on a floor (see no_rest_dt)
    collision_overlap,  // a step left two balls overlapping deeply (collide::CollisionPass::warn_overlap)
    collision_crossing, // two balls crossed each other within one step (collide/pair_crossings.hpp)
};
constexpr std::size_t warning_kind_count = static_cast<std::size_t>(WarningKind::collision_crossing) + 1;
// Per particle, a bit per kind it has been warned about (and one more: WarningSink).
using WarningBits = std::uint16_t;

struct Warning {
    WarningKind kind;
    std::uint32_t particle;
    double t;  // s: the step (frozen) or the monitor's sample (the others) that saw it
    // drag_validity: Re; mach: speed relative to the air (m/s); stability: drag stiffness k
    // (1/s); runaway, impact_cap: the speed the failed step reached (m/s); frozen: unused; no_rest: the
    // largest dt (s) at which explicit Euler comes to rest; collision_overlap: the overlap, as a share
    // of the pair's contact distance; collision_crossing: how far the pair's separation moved in the
    // step, in contact distances.
    double value = 0.0;
};

// Impacts one step may take before the particle is frozen and reported (a particle wedged in a
// corner by a force it cannot escape; no real scene comes near it).
constexpr int max_impacts_per_step = 64;

// Faster than light: Newtonian mechanics means nothing there, and such a state is a numerical
// blow-up on its way to overflow (1e48 m/s squared is still finite). Frozen like a NaN.
constexpr double runaway_speed_mps = 299792458.0;

// Explicit Euler gains speed on every bounce arc: a ball leaving the floor at u comes back at
// about u + g dt, so its rebound speeds tend to e g dt / (1 - e) instead of 0. Above
// dt = rest_speed (1 - e) / (e g) they never fall below rest_speed: the ball bounces (or, one
// that should slide, hops) forever. That dt for the model; +inf where the trap does not apply
// (another method, e = 0 or 1, no gravity).
double no_rest_dt(const Model& model);

// The text for the user; the limits it quotes come from the model the warning was raised under.
std::string warning_message(const Warning& w, const Model& model);

}  // namespace pl
