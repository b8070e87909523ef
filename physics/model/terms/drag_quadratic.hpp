// Quadratic (Newton) drag: a = -k |u| u, k = 1/2 rho Cd A / m (DragSettings::cd). Valid for
// roughly 1e3 < Re < 2e5. Power k |u|^3 into the drag ledger; stiffness 2 k |u| (the Jacobian).
// schema rows: see physics/model/schema/ (drag.model = quadratic, drag.cd)
#pragma once

#include "physics/model/terms/term.hpp"

#include <cmath>

namespace pl::terms {

struct DragQuadratic : DragBase<DragModel::quadratic> {
    double rate(const Vec3& u) const { return drag.k * std::sqrt(glm::dot(u, u)); }
    static double stiffness(double k, double /*re_scale*/, double u) { return 2.0 * k * u; }
};

}  // namespace pl::terms
