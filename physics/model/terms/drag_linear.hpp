// Linear (Stokes) drag: a = -k u, k = b / m, b = 6 pi mu R unless DragSettings::linear_b gives
// it (N s/m). Valid for Re < 1. Power k |u|^2 into the drag ledger; stiffness k.
#pragma once

#include "physics/model/field_schema.hpp"
#include "physics/model/schema/limits.hpp"
#include "physics/model/terms/term.hpp"

namespace pl::terms {

struct DragLinear : DragBase<DragModel::linear> {
    // a = -rate u
    double rate(const Vec3&) const { return drag.k; }
    // d|a|/du at relative speed u (1/s)
    static double stiffness(double k, double /*re_scale*/, double /*u*/) { return k; }
};

// Its preset row, "drag.b" (listed in physics/model/schema/drag_fields.hpp). Absent (null or
// omitted): Stokes b = 6 pi mu R from the air's viscosity and the radius.
inline constexpr schema::Field<DragSettings> linear_b_row =
    schema::optional_number("b", &DragSettings::linear_b, "N s/m", schema::non_negative(schema::max_linear_b), "b",
                            "Linear drag coefficient, F = -b v_rel; null or omitted: Stokes b = 6 pi mu R.")
        .when(schema::bit<DragModel::linear>());

}  // namespace pl::terms
