// Wind: the air moves with w(x, t) (WindField: constant, gust, shear, vortex), and the drag acts
// on u = v - w; the wind does work dot(a_drag, w) on the particle (the air_work ledger line).
// The four kinds are one term: they play the same role, share the ledger line and the counter,
// and are looked up through one out-of-line call (WindField::at, its switch of one function per
// kind in wind.cpp) that does not vectorise anyway; a type per kind would multiply the kernel's
// instantiations by four for no speed. Without a drag term the wind is never consulted.
#pragma once

#include "physics/model/field_schema.hpp"
#include "physics/model/schema/limits.hpp"
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

// Its preset rows, "world.wind" (the section is listed in physics/model/schema/wind_fields.hpp).
namespace pl::schema {

inline constexpr std::uint32_t constant_gust_shear = bit<WindKind::constant>() | bit<WindKind::gust>() | bit<WindKind::shear>();

inline constexpr Field<WindSettings> wind_rows[] = {
    enumeration<WindSettings, &WindSettings::kind>("kind", 5, "wind",
                                                   "w(x, t): none, constant, gust (mean + seeded bounded variation), "
                                                   "shear (power-law boundary layer) or vortex (Rankine)."),
    bounded_vec3("velocity", &WindSettings::velocity, "m/s", max_speed_mps, "velocity",
                 "constant: the wind; gust: the mean; shear: the wind at reference_height.")
        .when(constant_gust_shear),
    bounded_vec3("amplitude", &WindSettings::gust_amplitude, "m/s", max_speed_mps, "amplitude",
                 "Bounded variation per axis around the mean.")
        .when(bit<WindKind::gust>()),
    number("period", &WindSettings::gust_period_s, "s", positive(max_period_s), "period",
           "Dominant period of the variation.")
        .when(bit<WindKind::gust>()),
    unsigned_integer("seed", &WindSettings::gust_seed, max_seed, "seed", "Seed of the variation: same seed, same gusts.")
        .when(bit<WindKind::gust>()),
    number("reference_height", &WindSettings::reference_height_m, "m", positive(max_room_size_m), "ref. height",
           "Height above the floor where |w| = |velocity|.")
        .when(bit<WindKind::shear>()),
    number("exponent", &WindSettings::shear_exponent, "", closed(0.0, 1.0), "exponent",
           "Power-law (Hellmann) exponent: |w| ~ (height / reference_height)^exponent; 1/7 for open terrain.")
        .when(bit<WindKind::shear>()),
    vec3("center", &WindSettings::vortex_center, "m", symmetric(max_coordinate_m), "centre", "A point on the vortex axis.")
        .when(bit<WindKind::vortex>()),
    direction("axis", &WindSettings::vortex_axis, max_coordinate_m, "axis", "Direction of the vortex axis (not zero).")
        .when(bit<WindKind::vortex>()),
    number("max_speed", &WindSettings::vortex_max_speed, "m/s", non_negative(max_speed_mps), "max speed",
           "Tangential speed at core_radius.")
        .when(bit<WindKind::vortex>()),
    number("core_radius", &WindSettings::vortex_core_radius_m, "m", positive(max_room_size_m), "core radius",
           "Rankine vortex: the swirl rises linearly to max_speed at the core radius, then falls as 1/r.")
        .when(bit<WindKind::vortex>()),
};


}  // namespace pl::schema
