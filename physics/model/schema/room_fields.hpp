// Rows of the preset's "room" section (see physics/model/field_schema.hpp).
#pragma once

#include "physics/model/field_schema.hpp"
#include "physics/model/schema/limits.hpp"

namespace pl::schema {

inline constexpr Field<Room> room_rows[] = {
    vec3("center", &Room::center, "m", symmetric(max_coordinate_m), "centre", "The middle of the box.").required(),
    vec3("size", &Room::size, "m", positive(max_room_size_m), "size",
         "Edge lengths of the box; every particle must fit inside.")
        .required(),
};

template <>
struct SectionSchema<Room> : NoChildren {
    static constexpr const char* name = "room";
    static constexpr std::span<const Field<Room>> rows = room_rows;
};

}  // namespace pl::schema
