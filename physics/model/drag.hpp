// Aerodynamic drag on a sphere: per-particle coefficients and the Cd(Re) correlation.
#pragma once

#include "physics/model/scene.hpp"

namespace pl {

// Speed of sound in dry air at 20 C: the Mach numbers of the monitor's warning and the advisor.
constexpr double speed_of_sound_mps = 343.0;

// Coefficients precomputed per particle so the hot loop does no divisions or pi.
// Acceleration (drag force / mass) for relative velocity u = v - w:
//   linear:     a = -k u                    k = b / m
//   quadratic:  a = -k |u| u                k = 1/2 rho Cd A / m
//   sphere_re:  a = -k (Cd Re)(Re) u        k = pi R mu / (4 m), Re = re_scale |u|
// (Cd Re form: 1/2 rho A Cd |u| = pi R mu Cd Re / 4, which is finite as Re -> 0.)
struct DragCoefficients {
    double k = 0.0;
    double re_scale = 0.0;  // 2 R rho / mu: Re per m/s of relative speed
};

DragCoefficients drag_coefficients(const DragSettings& drag, const Air& air, double mass, double radius);

// Smooth-sphere drag coefficient times Re, from Morrison's correlation
// (F. A. Morrison, "Data Correlation for Drag Coefficient for Sphere", Michigan Tech, 2013):
//   Cd = 24/Re + 2.6 (Re/5) / (1 + (Re/5)^1.52)
//        + 0.411 (Re/2.63e5)^-7.94 / (1 + (Re/2.63e5)^-8) + 0.25 (Re/1e6) / (1 + Re/1e6)
// It follows the standard drag curve from creeping flow through the drag crisis near
// Re = 2.6e5 up to Re = 1e6 (within the ~10% scatter of the experimental data).
double sphere_cd_times_re(double re);
double sphere_cd(double re);  // re > 0

// Range of Re over which each model is trustworthy; leaving it raises a warning.
struct ReRange {
    double lo, hi;
};
ReRange drag_validity(DragModel model);

// Effective linear decay rate k (1/s) of the drag at relative speed u: the quantity whose
// product with dt decides explicit stability (k = b/m linear, 2 c|u|/m quadratic Jacobian).
double drag_stiffness(DragModel model, const DragCoefficients& c, double rel_speed);
// |a_drag| / |u| of the model at relative speed u (the terms' own rate; 0 without drag).
double drag_rate(DragModel model, const DragCoefficients& c, double rel_speed);

}  // namespace pl
