// Linear (Stokes) drag: a = -k u, k = b / m, b = 6 pi mu R unless DragSettings::linear_b gives
// it (N s/m). Valid for Re < 1. Power k |u|^2 into the drag ledger; stiffness k.
// schema rows: see physics/model/schema/ (drag.model = linear, drag.b)
#pragma once

#include "physics/model/terms/term.hpp"

namespace pl::terms {

struct DragLinear : DragBase<DragModel::linear> {
    // a = -rate u
    double rate(const Vec3&) const { return drag.k; }
    // d|a|/du at relative speed u (1/s)
    static double stiffness(double k, double /*re_scale*/, double /*u*/) { return k; }
};

}  // namespace pl::terms
