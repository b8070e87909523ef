// Wind: the air moves with w(x, t) (WindField: constant, gust, shear, vortex), and the drag acts
// on u = v - w; the wind does work dot(a_drag, w) on the particle (the air_work ledger line).
// The four kinds are one term: they play the same role, share the ledger line and the counter,
// and are looked up through one out-of-line call (WindField::at, its switch of one function per
// kind in wind.cpp) that does not vectorise anyway; a type per kind would multiply the kernel's
// instantiations by four for no speed. Without a drag term the wind is never consulted.
// schema rows: see physics/model/schema/ (world.wind)
#pragma once

#include "physics/model/terms/term.hpp"
#include "physics/model/wind.hpp"

namespace pl::terms {

struct Wind {
    static constexpr TermRole role = TermRole::air;
    static constexpr Ledger ledger = Ledger::air_work;
    static constexpr std::uint64_t ForceCounters::*counter = &ForceCounters::wind;
    static constexpr bool rest_is_uniform = false;
    static bool enabled(const Model& m) {
        return m.world.wind.kind != WindKind::none && m.drag.model != DragModel::none;
    }

    const WindField* wind = nullptr;
    mutable std::uint64_t evals = 0;

    void load(const TermInputs& in) { wind = in.wind; }
    Vec3 at(const Vec3& x, double t) const {
        ++evals;
        return wind->at(x, t);
    }
    // Work done by the moving air through the drag (W/kg).
    static double power(const Vec3& a_drag, const Vec3& w) { return glm::dot(a_drag, w); }
};

// The wind at the particle already looked up (the fast kernel looks it up for a whole chunk
// ahead of its vector loop): the same operations from w on, so the same bits.
struct KnownWind {
    static constexpr TermRole role = TermRole::air;
    static constexpr Ledger ledger = Ledger::air_work;
    static constexpr std::uint64_t ForceCounters::*counter = &ForceCounters::wind;
    static constexpr bool rest_is_uniform = false;

    Vec3 w{0.0};
    mutable std::uint64_t evals = 0;  // counted by the caller that looked w up

    void load(const TermInputs& in) {
        w.x = in.wx;
        w.y = in.wy;
        w.z = in.wz;
    }
    Vec3 at(const Vec3&, double) const { return w; }
    static double power(const Vec3& a_drag, const Vec3& w) { return Wind::power(a_drag, w); }
};

}  // namespace pl::terms
