// Rows of the preset's "drag" section (see physics/model/field_schema.hpp).
#pragma once

#include "physics/model/field_schema.hpp"
#include "physics/model/schema/limits.hpp"

namespace pl::schema {

inline constexpr Field<DragSettings> drag_rows[] = {
    enumeration<DragSettings, &DragSettings::model>(
        "model", 4, "drag model",
        "none: no air resistance. linear: Stokes, F = -6 pi mu R v (or an explicit b). quadratic: Newton, "
        "F = -1/2 rho Cd A |v| v. sphere_re: Cd(Re) for a smooth sphere over the whole Reynolds range (Morrison 2013)."),
    number("cd", &DragSettings::cd, "", positive(max_cd), "Cd", "Drag coefficient, 0.47 for a smooth sphere.")
        .when(bit<DragModel::quadratic>()),
    // Absent (null or omitted): Stokes b = 6 pi mu R from the air's viscosity and the radius.
    optional_number("b", &DragSettings::linear_b, "N s/m", non_negative(max_linear_b), "b",
                    "Linear drag coefficient, F = -b v_rel; null or omitted: Stokes b = 6 pi mu R.")
        .when(bit<DragModel::linear>()),
};

template <>
struct SectionSchema<DragSettings> : NoChildren {
    static constexpr const char* name = "drag";
    static constexpr std::span<const Field<DragSettings>> rows = drag_rows;
};

}  // namespace pl::schema
