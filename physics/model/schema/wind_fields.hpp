// The preset's "world.wind" section: its rows are the wind term's (physics/model/terms/wind.hpp).
#pragma once

#include "physics/model/field_schema.hpp"
#include "physics/model/schema/limits.hpp"
#include "physics/model/terms/wind.hpp"

namespace pl::schema {

template <>
struct SectionSchema<WindSettings> : NoChildren {
    static constexpr const char* name = "wind";
    static constexpr std::span<const Field<WindSettings>> rows = wind_rows;
};

}  // namespace pl::schema
