#include "physics/model/air_model.hpp"

#include <cmath>
#include <numbers>

namespace pl {

namespace {

// U.S. Standard Atmosphere 1976, Table 1 and eq. 18.
constexpr double earth_radius_m = 6356766.0;
constexpr double g0 = 9.80665;               // m/s^2
constexpr double gas_constant = 287.05287;   // R* / M0, J/(kg K)
constexpr double sea_level_temperature = 288.15;  // K
constexpr double sea_level_pressure = 101325.0;  // Pa
constexpr double lapse_rate = 0.0065;             // K/m, troposphere
constexpr double tropopause_m = 11000.0;          // geopotential
constexpr double tropopause_temperature = sea_level_temperature - lapse_rate * tropopause_m;  // 216.65 K

double geopotential(double geometric_m) { return earth_radius_m * geometric_m / (earth_radius_m + geometric_m); }
// dH/dh
double geopotential_slope(double geometric_m) {
    const double r = earth_radius_m / (earth_radius_m + geometric_m);
    return r * r;
}

double tropospheric_pressure(double temperature) {
    return sea_level_pressure * std::pow(temperature / sea_level_temperature, g0 / (gas_constant * lapse_rate));
}

}  // namespace

double isa_temperature(double altitude_m) {
    const double h = geopotential(altitude_m);
    return h <= tropopause_m ? sea_level_temperature - lapse_rate * h : tropopause_temperature;
}

double isa_pressure(double altitude_m) {
    const double h = geopotential(altitude_m);
    if (h <= tropopause_m) return tropospheric_pressure(sea_level_temperature - lapse_rate * h);
    return tropospheric_pressure(tropopause_temperature) *
           std::exp(-g0 * (h - tropopause_m) / (gas_constant * tropopause_temperature));
}

double isa_density(double altitude_m) { return isa_pressure(altitude_m) / (gas_constant * isa_temperature(altitude_m)); }

// rho = p / (R T), dp/dH = -rho g0, dT/dH = -L (0 above the tropopause):
// d rho / dH = rho (L - g0 / R) / T.
double isa_density_gradient(double altitude_m) {
    const double lapse = geopotential(altitude_m) <= tropopause_m ? lapse_rate : 0.0;
    return isa_density(altitude_m) * (lapse - g0 / gas_constant) / isa_temperature(altitude_m) *
           geopotential_slope(altitude_m);
}

double sutherland_viscosity(double t) { return 1.458e-6 * t * std::sqrt(t) / (t + 110.4); }

double air_density_at(const Air& air, double altitude_m) {
    return air.model == AirModel::isa ? isa_density(altitude_m) : air.density_kg_m3;
}

double air_viscosity_at(const Air& air, double altitude_m) {
    return air.model == AirModel::isa ? sutherland_viscosity(isa_temperature(altitude_m)) : air.viscosity_pa_s;
}

double air_density_gradient_at(const Air& air, double altitude_m) {
    return air.model == AirModel::isa ? isa_density_gradient(altitude_m) : 0.0;
}

double altitude_in_room(const Air& air, const Room& room, double y) { return air.base_altitude_m + (y - room.floor_y()); }

Air local_air(const Air& air, const Room& room, double y) {
    if (air.model == AirModel::constant) return air;
    const double h = altitude_in_room(air, room, y);
    Air local = air;
    local.model = AirModel::constant;
    local.density_kg_m3 = air_density_at(air, h);
    local.viscosity_pa_s = air_viscosity_at(air, h);
    return local;
}

double sphere_added_mass(double density, double radius) {
    return 0.5 * density * (4.0 / 3.0) * std::numbers::pi * radius * radius * radius;
}

double inertial_mass(const World& world, const Room& room, double mass, double radius, double y) {
    if (!world.added_mass) return mass;
    return mass + sphere_added_mass(local_air(world.air, room, y).density_kg_m3, radius);
}

}  // namespace pl
