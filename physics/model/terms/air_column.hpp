// The air column a particle moves through: ISA air whose density and viscosity change with the
// height (world.air.model = isa, physics/model/air_model.hpp), and the air it carries along
// (world.added_mass). Not a force of its own but a change of every force term's air and of the
// particle's inertia, so Forces (forces.hpp) evaluates the other terms through it:
//  * local air: at each evaluation the other terms are reloaded with the density and viscosity
//    at the particle's height (drag k and Re scale, buoyancy rho V, Magnus 1/2 rho A);
//  * added mass: a sphere accelerating through a fluid accelerates 1/2 rho V of it too (Lamb,
//    Hydrodynamics, 6th ed., section 92; C. E. Brennen, "A review of added mass and fluid
//    inertial forces", NCEL CR 82.010, 1982), so the inertial mass is M = m + 1/2 rho V while
//    gravity still acts on m and buoyancy on rho V: a = (F_gravity + F_buoyancy + F_drag +
//    F_lift) / M, i.e. every per-kg acceleration scaled by m / M. The steady-flow form: the
//    air's own acceleration (a gust) would add (1 + 1/2) rho V Dw/Dt, not modelled.
//  * both: M changes along the path with rho(h). Lagrange's equations for the kinetic energy
//    1/2 M(x) |v|^2 of particle plus entrained air (Lamb, section 117) give
//      M a = F + 1/2 |v|^2 grad M - (grad M . v) v,
//    whose extra force keeps 1/2 M v^2 + m g h - (work of F) exact. It is of order
//    (d rho/dh / rho) (m_a / M) |v|^2: 1e-4 of g at 10 m/s for a foam ball.
// Ledger: the drag and air lines stay per kg of m (the forces' own powers, unscaled); kinetic
// energy is 1/2 M v^2 (ParticleState::inertial_mass), and bounce, friction and rolling losses, computed from
// velocity changes, are per kg of M (generic_kernel.cpp). Only the generic kernel carries this
// term (scene.hpp: needs_generic_kernel).
#pragma once

#include "physics/model/air_model.hpp"
#include "physics/model/field_schema.hpp"
#include "physics/model/terms/term.hpp"

namespace pl::terms {

struct AirColumn {
    static constexpr TermRole role = TermRole::medium;
    static constexpr Ledger ledger = Ledger::none;
    static constexpr std::uint64_t ForceCounters::*counter = &ForceCounters::air_column;
    static constexpr bool rest_is_uniform = false;
    static bool enabled(const Model& m) { return air_column_matters(m); }

    // The air at one height, as the other terms and the inertia see it.
    struct Here {
        double density = 0.0;
        double scale = 1.0;         // m / M
        double growth = 0.0;        // (dM/dy) / M, 1/m
    };

    const Model* model = nullptr;
    TermInputs inputs;          // the particle's inputs; the air-dependent ones are replaced per height
    bool varies = false;        // isa: the air changes with the height
    double half_volume = 0.0;   // 1/2 V where world.added_mass, else 0
    mutable std::uint64_t evals = 0;

    void load(const TermInputs& in) {
        inputs = in;
        model = in.model;
        varies = model->world.air.model != AirModel::constant;
        half_volume = model->world.added_mass ? sphere_added_mass(1.0, in.radius) : 0.0;
    }

    Here at(double y) const {
        ++evals;
        const Air& air = model->world.air;
        const double h = altitude_in_room(air, model->room, y);
        Here here;
        here.density = air_density_at(air, h);
        const double inertial = inputs.mass + half_volume * here.density;
        here.scale = inputs.mass / inertial;
        here.growth = half_volume * air_density_gradient_at(air, h) / inertial;
        return here;
    }
    // The inputs of the other terms for the air at height y.
    TermInputs inputs_at(double y) const {
        const Air air = local_air(model->world.air, model->room, y);
        const DragCoefficients c = drag_coefficients(model->drag, air, inputs.mass, inputs.radius);
        TermInputs in = inputs;
        in.k = c.k;
        in.re_scale = c.re_scale;
        in.air_density = air.density_kg_m3;
        return in;
    }
    // The acceleration of the particle with its air: the forces' per-kg-of-m sum `a`, divided
    // by M / m, plus the change of M along the path (file comment).
    static Vec3 inertial(const Here& here, const Vec3& a, const Vec3& v) {
        Vec3 out = here.scale * a;
        if (here.growth != 0.0) out += here.growth * (0.5 * glm::dot(v, v) * Vec3(0.0, 1.0, 0.0) - v.y * v);
        return out;
    }
};

// Its preset row, "world.added_mass" (listed in physics/model/schema/world_fields.hpp).
inline constexpr schema::Field<World> added_mass_row = schema::boolean(
    "added_mass", &World::added_mass, "added mass",
    "true: each particle accelerates 1/2 rho_air V of air along with it (the added mass of a sphere), so its "
    "inertia is m + 1/2 rho_air V while gravity acts on m. Matters where buoyancy does: light, large particles.");

}  // namespace pl::terms
