// Buoyancy (Archimedes): the weight of the displaced air pushes up, F = -rho_air V g with
// V = 4/3 pi R^3, so per unit mass a = -(rho_air V / m) g, constant for each particle (World::
// buoyancy turns it on; rho_air is World::air's density). Stiffness 0 (it does not depend on v).
// Ledger: its work, the power dot(a, v) integrated by the method alongside x and v, goes to the
// air_work line (work done on the particle by the air: the wind through the drag, and this), so
// the residual stays the method's own error. Not as a reduced effective potential m (1 - rho V/m)
// g h: that would need every place that computes the potential (initial energy, relaunch, the
// studies, the UI's ledger) to know the particle's buoyancy, where a ledger line needs none of them.
#pragma once

#include "physics/model/field_schema.hpp"
#include "physics/model/terms/term.hpp"

#include <numbers>

namespace pl::terms {

struct Buoyancy {
    static constexpr TermRole role = TermRole::body;
    static constexpr Ledger ledger = Ledger::air_work;
    static constexpr std::uint64_t ForceCounters::*counter = &ForceCounters::buoyancy;
    static constexpr bool rest_is_uniform = false;  // depends on each particle's radius and mass
    static bool enabled(const Model& m) { return m.world.buoyancy; }

    double displaced = 0.0;  // rho_air V / m: the displaced air's mass per kg of particle
    mutable std::uint64_t evals = 0;

    void load(const TermInputs& in) {
        const double volume = (4.0 / 3.0) * std::numbers::pi * in.radius * in.radius * in.radius;
        displaced = in.air_density * volume / in.mass;
    }
    Vec3 acceleration(const Vec3& g) const { return -displaced * g; }
    static double power(const Vec3& a, const Vec3& v) { return glm::dot(a, v); }
    static double stiffness(double, double, double) { return 0.0; }
};

// Its preset row, "world.buoyancy" (listed in physics/model/schema/world_fields.hpp).
inline constexpr schema::Field<World> buoyancy_row = schema::boolean(
    "buoyancy", &World::buoyancy, "buoyancy",
    "true: the weight of the displaced air, rho_air V g, lifts each particle (Archimedes). It matters when "
    "the particle's density is not far above the air's: a 1 kg/m^3 difference is a 1 g/cm^3 ball's 0.12%, "
    "a foam ball's tens of percent.");

}  // namespace pl::terms
