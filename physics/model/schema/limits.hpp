// Sane limits of the preset format: far beyond any lab experiment, small enough that products
// of them stay finite. Used by the section rows (physics/model/schema/*_fields.hpp).
#pragma once

#include <cstdint>
#include <limits>

namespace pl::schema {

constexpr double max_coordinate_m = 1e6;
constexpr double max_room_size_m = 1e6;
constexpr double max_speed_mps = 1e5;
constexpr double max_gravity_mps2 = 1e4;
constexpr double max_spin_rad_s = 1e5;
constexpr double max_mass_kg = 1e6;
// Lightest particle: about a 1 um dust grain (4e-15 kg). Lighter ones are Brownian, outside this
// model, and a mass such as 5e-324 made the drag stiffness infinite (the particle froze).
constexpr double min_mass_kg = 1e-15;
constexpr double max_density_kg_m3 = 1e5;
constexpr double max_viscosity_pa_s = 1e3;
constexpr double max_cd = 100.0;
constexpr double max_linear_b = 1e6;
constexpr double max_friction = 10.0;
constexpr double max_rest_speed_mps = 1e3;
constexpr double max_dt_s = 1.0;
constexpr double max_tolerance = 1.0;
constexpr double max_period_s = 1e6;
// An expectation's tolerance, in its quantity's unit (s, m, J or a count).
constexpr double max_expectation_tolerance = 1e12;
// Seeds take every uint64 (the GUI's number field refuses a seed it cannot show exactly).
constexpr std::uint64_t max_seed = std::numeric_limits<std::uint64_t>::max();
// Largest particle count a preset may ask for (explicit + emitted).
constexpr std::uint64_t max_particles = 2'000'000;

}  // namespace pl::schema
