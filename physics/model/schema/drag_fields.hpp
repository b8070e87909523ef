// Rows of the preset's "drag" section (see physics/model/field_schema.hpp): the model selector here,
// each model's own rows in its term header (cd: drag_quadratic.hpp, b: drag_linear.hpp).
#pragma once

#include "physics/model/field_schema.hpp"
#include "physics/model/schema/limits.hpp"
#include "physics/model/terms/drag_linear.hpp"
#include "physics/model/terms/drag_quadratic.hpp"
#include "physics/model/terms/magnus.hpp"

namespace pl::schema {

inline constexpr Field<DragSettings> drag_rows[] = {
    enumeration<DragSettings, &DragSettings::model>(
        "model", 4, "drag model",
        "none: no air resistance. linear: Stokes, F = -6 pi mu R v (or an explicit b). quadratic: Newton, "
        "F = -1/2 rho Cd A |v| v. sphere_re: Cd(Re) for a smooth sphere over the whole Reynolds range (Morrison 2013)."),
    terms::cd_row,
    terms::linear_b_row,
    terms::lift_row,
    terms::spin_decay_row,
};

template <>
struct SectionSchema<DragSettings> : NoChildren {
    static constexpr const char* name = "drag";
    static constexpr std::span<const Field<DragSettings>> rows = drag_rows;
};

}  // namespace pl::schema
