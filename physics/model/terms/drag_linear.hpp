// Linear (Stokes) drag: a = -k u, k = b / m, b = 6 pi mu R unless DragSettings::linear_b gives
// it (N s/m). Valid for Re < 1. Power k |u|^2 into the drag ledger; stiffness k.
// schema rows: see physics/model/schema/ (drag.model = linear, drag.b)
#pragma once

#include "physics/model/terms/term.hpp"

namespace pl::terms {

struct DragLinear {
    static constexpr TermRole role = TermRole::drag;
    static constexpr Ledger ledger = Ledger::drag;
    static constexpr std::uint64_t ForceCounters::*counter = &ForceCounters::drag;
    static constexpr bool rest_is_uniform = true;  // no force at u = 0
    static constexpr DragModel model = DragModel::linear;
    static bool enabled(const Model& m) { return m.drag.model == model; }

    DragCoefficients drag{};
    mutable std::uint64_t evals = 0;

    void load(const TermInputs& in) { drag = {in.k, in.re_scale}; }
    // a = -rate u
    double rate(const Vec3&) const { return drag.k; }
    // d|a|/du at relative speed u (1/s)
    static double stiffness(double k, double /*re_scale*/, double /*u*/) { return k; }
};

}  // namespace pl::terms
