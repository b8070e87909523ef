// Quadratic (Newton) drag: a = -k |u| u, k = 1/2 rho Cd A / m (DragSettings::cd). Valid for
// roughly 1e3 < Re < 2e5. Power k |u|^3 into the drag ledger; stiffness 2 k |u| (the Jacobian).
// schema rows: see physics/model/schema/ (drag.model = quadratic, drag.cd)
#pragma once

#include "physics/model/terms/term.hpp"

#include <cmath>

namespace pl::terms {

struct DragQuadratic {
    static constexpr TermRole role = TermRole::drag;
    static constexpr Ledger ledger = Ledger::drag;
    static constexpr std::uint64_t ForceCounters::*counter = &ForceCounters::drag;
    static constexpr bool rest_is_uniform = true;  // no force at u = 0
    static constexpr DragModel model = DragModel::quadratic;
    static bool enabled(const Model& m) { return m.drag.model == model; }

    DragCoefficients drag{};
    mutable std::uint64_t evals = 0;

    void load(const TermInputs& in) { drag = {in.k, in.re_scale}; }
    double rate(const Vec3& u) const { return drag.k * std::sqrt(glm::dot(u, u)); }
    static double stiffness(double k, double /*re_scale*/, double u) { return 2.0 * k * u; }
};

}  // namespace pl::terms
