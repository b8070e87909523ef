// How often would the particles of a scene meet? The advisor's estimate for its collisions row
// (advisor_terms.cpp), from kinetic theory of a dilute gas of hard spheres (Chapman & Cowling,
// "The Mathematical Theory of Non-uniform Gases", 3rd ed. 1970; Reif, "Fundamentals of
// Statistical and Thermal Physics", 1965, ch. 12), plus a check of the settled state: balls
// that cannot all lie on the floor in one layer must stack, whatever the rate.
//
//   n      = N / V                                   number density, V the room's volume
//   phi    = sum_i 4/3 pi r_i^3 / V                  volume fraction
//   sigma  = mean over pairs i < j of pi (r_i + r_j)^2   cross-section (mixed radii: pair mean)
//   lambda = 1 / (sqrt(2) n sigma)                   mean free path (the sqrt 2: relative speed)
//   v      = rms over particles of sqrt(|v0_i|^2 + 2 g h_i)   characteristic speed
//   nu     = v / lambda                              collisions per particle per second
//   nu T, N nu T / 2                                 per particle and in all, over T seconds
//
// v is each particle's speed when it reaches the floor without drag (energy conservation from
// its start, h_i the height of its lowest point over the floor): the largest speed it has in the
// run, so the rate is an upper bound and "collisions do not matter" is the safe side.
// Settled state: the balls' footprints sum_i pi r_i^2 need sum / (phi_2 A) layers on a floor of
// area A, phi_2 = 0.84 the random close packing of disks (Meer, Galoustian, de Falco Manuel and
// Weeks, "Circle radius distributions determine random close packing density", 2024; the densest
// packing, hexagonal, is pi / (2 sqrt 3) = 0.907). More than one layer: they must stack.
#pragma once

#include "physics/model/scene.hpp"

#include <limits>
#include <span>
#include <string>

namespace pl {

inline constexpr double disk_random_close_packing = 0.84;
// The advisor judges a term by any particle's metrics: a single collision moves both particles
// far beyond millimetre tolerances, so collisions matter once the scene expects one in all.
inline constexpr double collisions_that_matter = 1.0;

struct CollisionEstimate {
    bool applicable = false;  // two particles or more
    std::size_t particles = 0;           // N, every particle of the scene
    std::size_t measured_particles = 0;  // how many the advisor's runs use (its first 100)
    double room_volume_m3 = 0.0;
    double number_density_m3 = 0.0;  // n
    double volume_fraction = 0.0;    // phi
    double cross_section_m2 = 0.0;   // sigma
    double mean_free_path_m = std::numeric_limits<double>::infinity();  // lambda
    double speed_m_s = 0.0;          // v
    double rate_per_s = 0.0;         // nu
    double duration_s = 0.0;         // T
    double per_particle = 0.0;       // nu T
    double total = 0.0;              // N nu T / 2
    double floor_area_m2 = 0.0;      // 0 without gravity (no floor)
    double footprint_m2 = 0.0;       // sum pi r^2
    double layers = 0.0;             // footprint / (phi_2 A)
    bool must_stack = false;         // layers > 1
    bool matters = false;            // must_stack, or total >= collisions_that_matter
};

// The estimate for `particles` (all the scene's) in `model`'s room and gravity over `duration_s`.
CollisionEstimate estimate_collisions(const Model& model, std::span<const ParticleSpec> particles, double duration_s);

// sigma for mixed radii in O(N): sum_{i<j} (r_i + r_j)^2 = (N - 2) sum r^2 + (sum r)^2.
double mean_pair_cross_section(std::span<const ParticleSpec> particles);

// The reason in words: "2000 balls cannot lie in one layer on 1 m^2 of floor (they need 2.9
// layers)" or "0.002 expected collisions per particle over 5 s (0.1 in all; mean free path 40 m,
// volume fraction 1e-06)".
std::string collision_reason(const CollisionEstimate& e);

// On when the estimate or the measured runs say collisions matter.
inline bool recommend_collisions(const CollisionEstimate& e, bool measured_matters) {
    return e.applicable && (e.matters || measured_matters);
}

}  // namespace pl
