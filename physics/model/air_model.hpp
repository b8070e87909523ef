// The air's density and viscosity where a particle is (world.air.model):
//   constant  the preset's density and viscosity everywhere;
//   isa       the International Standard Atmosphere (ISO 2533:1975, identical below 32 km to the
//             U.S. Standard Atmosphere 1976, NOAA-S/T 76-1562, eqs. 23, 33, 42, 51):
//               H = r0 h / (r0 + h)                   geopotential altitude, r0 = 6356766 m
//               T = 288.15 - 0.0065 H  K               troposphere, H <= 11000 m
//               p = 101325 (T / 288.15)^(g0 / (R L))  Pa, g0 / (R L) = 5.25588
//               rho = p / (R T)                        R = 287.05287 J/(kg K)
//               mu = 1.458e-6 T^1.5 / (T + 110.4)      Sutherland's law, Pa s
//             above H = 11000 m the isothermal layer T = 216.65 K, p = p11 exp(-g0 (H - 11000) / (R T)).
// The altitude h is geometric: world.air.base_altitude (the floor's) plus the particle's height
// above the floor. The standard's formulas run on geopotential altitude H; converting gives the
// standard's tables by geometric altitude (1.2250 kg/m^3 at 0 m, 1.0581 at 1500 m, 0.90925 at
// 3000 m). A standard day, not weather: real air differs by several percent with temperature
// and humidity. The advisor and the force terms share these functions.
#pragma once

#include "physics/model/scene.hpp"

namespace pl {

// The range of world.air.base_altitude: the troposphere, from the Dead Sea shore to the tropopause.
constexpr double min_base_altitude_m = -500.0;
constexpr double max_base_altitude_m = 11000.0;

double isa_temperature(double altitude_m);  // K
double isa_pressure(double altitude_m);     // Pa
double isa_density(double altitude_m);      // kg/m^3
// d rho / d h along geometric altitude (kg/m^4, negative).
double isa_density_gradient(double altitude_m);
double sutherland_viscosity(double temperature_k);  // Pa s

// The air's density (kg/m^3) and dynamic viscosity (Pa s) at a geometric altitude (m); constant
// air ignores the altitude.
double air_density_at(const Air& air, double altitude_m);
double air_viscosity_at(const Air& air, double altitude_m);
// d rho / d h at that altitude (0 for constant air).
double air_density_gradient_at(const Air& air, double altitude_m);

// The geometric altitude of height y in the room: base_altitude + (y - floor).
double altitude_in_room(const Air& air, const Room& room, double y);
// The air at height y in the room, as constant air (what drag_coefficients takes).
Air local_air(const Air& air, const Room& room, double y);

// Added mass of a sphere of radius R in air of density rho: 1/2 rho V, V = 4/3 pi R^3 (Lamb,
// Hydrodynamics, 6th ed., section 92).
double sphere_added_mass(double density, double radius);
// The particle's inertial mass at height y: m, plus the added mass where world.added_mass.
double inertial_mass(const World& world, const Room& room, double mass, double radius, double y);

}  // namespace pl
