// Gravity: a = g, uniform (World::gravity, m/s^2). Its work is the potential energy
// (energy.hpp), exact, so it has no ledger line of its own; stiffness 0.
// schema rows: see physics/model/schema/ (world.gravity)
#pragma once

#include "physics/model/terms/term.hpp"

namespace pl::terms {

struct Gravity {
    static constexpr TermRole role = TermRole::gravity;
    static constexpr Ledger ledger = Ledger::potential;
    static constexpr std::uint64_t ForceCounters::*counter = &ForceCounters::gravity;
    static constexpr bool rest_is_uniform = true;
    static bool enabled(const Model&) { return true; }

    Vec3 gravity{0.0};
    mutable std::uint64_t evals = 0;

    void load(const TermInputs& in) {
        gravity.x = in.gx;
        gravity.y = in.gy;
        gravity.z = in.gz;
    }
};

}  // namespace pl::terms
