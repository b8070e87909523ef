// Rows of the preset's "world.air" section (see physics/model/field_schema.hpp).
#pragma once

#include "physics/model/air_model.hpp"
#include "physics/model/field_schema.hpp"
#include "physics/model/schema/limits.hpp"

namespace pl::schema {

inline constexpr Field<Air> air_rows[] = {
    enumeration<Air, &Air::model>("model", 2, "air model",
                                  "constant: the density and viscosity below, everywhere; isa: the International "
                                  "Standard Atmosphere (ISO 2533) at each particle's altitude, base_altitude plus its "
                                  "height above the floor (density and viscosity derived; the two fields are ignored)."),
    number("density", &Air::density_kg_m3, "kg/m^3", positive(max_density_kg_m3), "density",
           "constant: 1.225 at sea level (ISA, 15 C); about 0.74 at 5000 m.")
        .when(bit<AirModel::constant>()),
    number("viscosity", &Air::viscosity_pa_s, "Pa s", positive(max_viscosity_pa_s), "viscosity",
           "constant: dynamic viscosity, 1.81e-5 for air at 15 C.")
        .when(bit<AirModel::constant>()),
    number("base_altitude", &Air::base_altitude_m, "m", closed(min_base_altitude_m, max_base_altitude_m),
           "base altitude",
           "isa: geometric altitude of the room's floor above sea level (troposphere): 1.2250 kg/m^3 at 0 m, "
           "0.9093 at 3000 m.")
        .when(bit<AirModel::isa>()),
};

template <>
struct SectionSchema<Air> : NoChildren {
    static constexpr const char* name = "air";
    static constexpr std::span<const Field<Air>> rows = air_rows;
};

}  // namespace pl::schema
