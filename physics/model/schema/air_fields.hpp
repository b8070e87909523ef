// Rows of the preset's "world.air" section (see physics/model/field_schema.hpp).
#pragma once

#include "physics/model/field_schema.hpp"
#include "physics/model/schema/limits.hpp"

namespace pl::schema {

inline constexpr Field<Air> air_rows[] = {
    number("density", &Air::density_kg_m3, "kg/m^3", positive(max_density_kg_m3), "density",
           "1.225 at sea level (ISA, 15 C); about 0.74 at 5000 m."),
    number("viscosity", &Air::viscosity_pa_s, "Pa s", positive(max_viscosity_pa_s), "viscosity",
           "Dynamic viscosity, 1.81e-5 for air at 15 C."),
};

template <>
struct SectionSchema<Air> : NoChildren {
    static constexpr const char* name = "air";
    static constexpr std::span<const Field<Air>> rows = air_rows;
};

}  // namespace pl::schema
