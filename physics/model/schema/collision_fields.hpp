// Rows of the preset's "collisions" section (see physics/model/field_schema.hpp).
#pragma once

#include "physics/model/field_schema.hpp"
#include "physics/model/schema/limits.hpp"

namespace pl::schema {

inline constexpr Field<CollisionSettings> collision_rows[] = {
    boolean("enabled", &CollisionSettings::enabled, "particles collide",
            "true: particles bounce off each other (sphere-sphere impulses); false: they pass through each other."),
    number("restitution", &CollisionSettings::restitution, "", closed(0.0, 1.0), "restitution e",
           "Normal separation speed / approach speed of a colliding pair, 0 (sticks) .. 1 (no loss)."),
    number("friction", &CollisionSettings::friction, "", non_negative(max_friction), "friction mu",
           "Coulomb friction coefficient between two particles' surfaces."),
};

template <>
struct SectionSchema<CollisionSettings> : NoChildren {
    static constexpr const char* name = "collisions";
    static constexpr std::span<const Field<CollisionSettings>> rows = collision_rows;
};

}  // namespace pl::schema
