// Rows of the preset's "emitter" section (see physics/model/field_schema.hpp). The ranges'
// order (min <= max) and the radius's fit in the room are cross-field checks in the reader.
#pragma once

#include "physics/model/field_schema.hpp"
#include "physics/model/schema/limits.hpp"

namespace pl::schema {

inline constexpr Field<Emitter> emitter_rows[] = {
    unsigned_integer("count", &Emitter::count, max_particles, "count",
                     "Particles the emitter creates (seeded: the same seed gives the same particles).")
        .required(),
    unsigned_integer("seed", &Emitter::seed, max_seed, "seed", "Seed of the positions, speeds, directions and sizes."),
    vec3("region_min", &Emitter::region_min, "m", symmetric(max_coordinate_m), "region min",
         "Lowest corner of the box the centres are drawn from."),
    vec3("region_max", &Emitter::region_max, "m", symmetric(max_coordinate_m), "region max",
         "Highest corner of that box, >= region_min per axis."),
    number("speed_min", &Emitter::speed_min, "m/s", non_negative(max_speed_mps), "speed min", "Slowest launch speed."),
    number("speed_max", &Emitter::speed_max, "m/s", non_negative(max_speed_mps), "speed max",
           "Fastest launch speed, >= speed_min."),
    direction("direction", &Emitter::direction, max_coordinate_m, "direction", "Mean launch direction (not zero)."),
    number("spread_deg", &Emitter::spread_deg, "deg", closed(0.0, 180.0), "spread",
           "Directions are uniform within this angle of direction (180: all directions)."),
    number("mass_min", &Emitter::mass_min, "kg", at_least(min_mass_kg, max_mass_kg), "mass min", "Lightest particle."),
    number("mass_max", &Emitter::mass_max, "kg", at_least(min_mass_kg, max_mass_kg), "mass max", "Heaviest particle, >= mass_min."),
    number("radius_min", &Emitter::radius_min, "m", positive(max_room_size_m), "radius min", "Smallest radius."),
    number("radius_max", &Emitter::radius_max, "m", positive(max_room_size_m), "radius max",
           "Largest radius, >= radius_min and less than half the room's smallest size."),
};

template <>
struct SectionSchema<Emitter> : NoChildren {
    static constexpr const char* name = "emitter";
    static constexpr std::span<const Field<Emitter>> rows = emitter_rows;
};

}  // namespace pl::schema
