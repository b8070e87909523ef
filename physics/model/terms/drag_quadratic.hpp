// Quadratic (Newton) drag: a = -k |u| u, k = 1/2 rho Cd A / m (DragSettings::cd). Valid for
// roughly 1e3 < Re < 2e5. Power k |u|^3 into the drag ledger; stiffness 2 k |u| (the Jacobian).
#pragma once

#include "physics/model/field_schema.hpp"
#include "physics/model/schema/limits.hpp"
#include "physics/model/terms/term.hpp"

#include <cmath>

namespace pl::terms {

struct DragQuadratic : DragBase<DragModel::quadratic> {
    double rate(const Vec3& u) const { return drag.k * std::sqrt(glm::dot(u, u)); }
    static double stiffness(double k, double /*re_scale*/, double u) { return 2.0 * k * u; }
};

// Its preset row, "drag.cd" (listed in physics/model/schema/drag_fields.hpp).
inline constexpr schema::Field<DragSettings> cd_row =
    schema::number("cd", &DragSettings::cd, "", schema::positive(schema::max_cd), "Cd",
                   "Drag coefficient, 0.47 for a smooth sphere.")
        .when(schema::bit<DragModel::quadratic>());

}  // namespace pl::terms
