// Rows of the preset's "world.wind" section (see physics/model/field_schema.hpp).
#pragma once

#include "physics/model/field_schema.hpp"
#include "physics/model/schema/limits.hpp"

namespace pl::schema {

inline constexpr std::uint32_t constant_gust_shear = bit<WindKind::constant>() | bit<WindKind::gust>() | bit<WindKind::shear>();

inline constexpr Field<WindSettings> wind_rows[] = {
    enumeration<WindSettings, &WindSettings::kind>("kind", 5, "wind",
                                                   "w(x, t): none, constant, gust (mean + seeded bounded variation), "
                                                   "shear (power-law boundary layer) or vortex (Rankine)."),
    bounded_vec3("velocity", &WindSettings::velocity, "m/s", max_speed_mps, "velocity",
                 "constant: the wind; gust: the mean; shear: the wind at reference_height.")
        .when(constant_gust_shear),
    bounded_vec3("amplitude", &WindSettings::gust_amplitude, "m/s", max_speed_mps, "amplitude",
                 "Bounded variation per axis around the mean.")
        .when(bit<WindKind::gust>()),
    number("period", &WindSettings::gust_period_s, "s", positive(max_period_s), "period",
           "Dominant period of the variation.")
        .when(bit<WindKind::gust>()),
    unsigned_integer("seed", &WindSettings::gust_seed, max_seed, "seed", "Seed of the variation: same seed, same gusts.")
        .when(bit<WindKind::gust>()),
    number("reference_height", &WindSettings::reference_height_m, "m", positive(max_room_size_m), "ref. height",
           "Height above the floor where |w| = |velocity|.")
        .when(bit<WindKind::shear>()),
    number("exponent", &WindSettings::shear_exponent, "", closed(0.0, 1.0), "exponent",
           "Power-law (Hellmann) exponent: |w| ~ (height / reference_height)^exponent; 1/7 for open terrain.")
        .when(bit<WindKind::shear>()),
    vec3("center", &WindSettings::vortex_center, "m", symmetric(max_coordinate_m), "centre", "A point on the vortex axis.")
        .when(bit<WindKind::vortex>()),
    direction("axis", &WindSettings::vortex_axis, max_coordinate_m, "axis", "Direction of the vortex axis (not zero).")
        .when(bit<WindKind::vortex>()),
    number("max_speed", &WindSettings::vortex_max_speed, "m/s", non_negative(max_speed_mps), "max speed",
           "Tangential speed at core_radius.")
        .when(bit<WindKind::vortex>()),
    number("core_radius", &WindSettings::vortex_core_radius_m, "m", positive(max_room_size_m), "core radius",
           "Rankine vortex: the swirl rises linearly to max_speed at the core radius, then falls as 1/r.")
        .when(bit<WindKind::vortex>()),
};

template <>
struct SectionSchema<WindSettings> : NoChildren {
    static constexpr const char* name = "wind";
    static constexpr std::span<const Field<WindSettings>> rows = wind_rows;
};

}  // namespace pl::schema
