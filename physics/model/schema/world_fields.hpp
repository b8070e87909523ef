// Rows of the preset's "world" section: gravity, and the air and wind sections inside it.
#pragma once

#include "physics/model/field_schema.hpp"
#include "physics/model/schema/air_fields.hpp"
#include "physics/model/schema/limits.hpp"
#include "physics/model/schema/wind_fields.hpp"
#include "physics/model/terms/air_column.hpp"
#include "physics/model/terms/buoyancy.hpp"

namespace pl::schema {

inline constexpr Field<World> world_rows[] = {
    vec3("gravity", &World::gravity, "m/s^2", symmetric(max_gravity_mps2), "gravity", "y is up: [0, -9.81, 0] on Earth."),
    terms::buoyancy_row,
    terms::added_mass_row,
};

inline constexpr ChildInfo air_child{"air", "The air the particles move through (drag and wind act through it)."};
inline constexpr ChildInfo wind_child{"wind", "The wind w(x, t); drag acts on the velocity relative to it."};

template <>
struct SectionSchema<World> {
    static constexpr const char* name = "world";
    static constexpr std::span<const Field<World>> rows = world_rows;
    template <class V>
    static void children(V&& visit) {
        visit(air_child, &World::air);
        visit(wind_child, &World::wind);
    }
};

}  // namespace pl::schema
