// What every force term declares (see README, Architecture). A term is a struct with
//   role     body (a constant force per particle), drag (a = -rate(u) u, u = v - w; at most
//            one drag term is enabled), air (the wind w(x, t) the drag sees; needs a drag) or
//            lift (a = lift(u, t), normal to u, from the particle's spin: terms/magnus.hpp) or
//            medium (the air column: the others' air at the particle's height and the inertia
//            of the air it carries, terms/air_column.hpp);
//   ledger   which ledger line its work goes to (potential: gravity's work is the potential
//            energy; drag: dissipated by drag; air_work: work done by the air; none);
//   counter  its slot in ForceCounters, and `evals`, its evaluation count;
//   enabled(model)  whether a scene enables it (the kernel is built from the enabled list);
//   rest_is_uniform whether the forces at rest (v = 0) are the same for every particle with it
//            (the fast kernel then skips particles resting still);
//   load(TermInputs) fills its per-particle parameters from scalars (the vector loops keep the
//            functor in registers only if nothing is copied as a whole);
// and its acceleration, power (W/kg, for the energy ledger) and stiffness (1/s, for the
// stability guard and the exponential step). Everything is per unit mass.
#pragma once

#include "physics/model/drag.hpp"
#include "physics/model/scene.hpp"
#include "physics/model/terms/counters.hpp"

#include <glm/geometric.hpp>

#include <cstdint>

namespace pl {

class WindField;
struct SpinClock;

enum class TermRole { gravity, body, drag, air, lift, medium };
enum class Ledger { none, potential, drag, air_work };

// Per-particle and scene scalars a term may load (drag constants, wind known in advance, ...).
struct TermInputs {
    double gx = 0.0, gy = 0.0, gz = 0.0;  // the scene's gravity
    const WindField* wind = nullptr;
    double k = 0.0, re_scale = 0.0;       // the particle's DragCoefficients
    double wx = 0.0, wy = 0.0, wz = 0.0;  // the wind at the particle, where looked up ahead
    double mass = 0.0, radius = 0.0;
    double air_density = 0.0;
    LiftModel lift = LiftModel::none;  // Magnus: the lift correlation (the scene's)
    const SpinClock* spin = nullptr;   // Magnus: the particle's spin
    const Model* model = nullptr;      // the air column: the scene (air, room, drag settings)
};

// The scene's part of the inputs (the per-particle fields left at 0).
inline TermInputs scene_inputs(const Model& m, const WindField* wind) {
    TermInputs in;
    in.gx = m.world.gravity.x;
    in.gy = m.world.gravity.y;
    in.gz = m.world.gravity.z;
    in.wind = wind;
    in.air_density = m.world.air.density_kg_m3;
    in.lift = m.drag.lift;
    in.model = &m;
    return in;
}

// What the drag terms share: role, ledger line, counter and the per-particle coefficients
// (DragCoefficients, precomputed per particle by drag_coefficients). Each drag term adds its
// rate(u) (a = -rate u) and its stiffness(k, re_scale, |u|).
template <DragModel M>
struct DragBase {
    static constexpr TermRole role = TermRole::drag;
    static constexpr Ledger ledger = Ledger::drag;
    static constexpr std::uint64_t ForceCounters::*counter = &ForceCounters::drag;
    static constexpr bool rest_is_uniform = true;  // no force at u = 0
    static constexpr DragModel model = M;
    static bool enabled(const Model& m) { return m.drag.model == M; }

    DragCoefficients drag{};
    mutable std::uint64_t evals = 0;

    void load(const TermInputs& in) { drag = {in.k, in.re_scale}; }
};

// Power dissipated by a drag a = -rate u (W/kg): rate |u|^2 >= 0.
inline double drag_power(double rate, const Vec3& u) { return rate * glm::dot(u, u); }

}  // namespace pl
