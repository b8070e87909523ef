#include "physics/studies/advisor_terms.hpp"

#include "physics/model/air_model.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>

namespace pl {

DragSettings candidate_drag(DragModel model, const DragSettings& configured) {
    if (model == configured.model) return configured;
    DragSettings d;
    d.model = model;
    if (configured.model == DragModel::quadratic) d.cd = configured.cd;
    // Magnus lift is a term of its own: every drag candidate keeps it as configured.
    d.lift = configured.lift;
    d.spin_decay_s = configured.spin_decay_s;
    return d;
}

namespace {

template <DragModel D>
bool use_drag(Model& m) {
    if (m.drag.model == D) return false;
    m.drag = candidate_drag(D, m.drag);
    return true;
}

bool as_configured(Model&) { return false; }

// Drag on: the variant's own drag model, or the reference when it has none.
bool drag_on(Model& m) { return m.drag.model == DragModel::none && use_reference_drag(m); }

const char* wind_not_applicable(const Model& m, std::size_t) {
    if (m.world.wind.kind == WindKind::none) return "no wind in this scene";
    if (m.drag.model == DragModel::none) return "drag is off, so wind has no effect";
    return nullptr;
}

std::string drag_note(const TermContext& c) { return fmt::format("max drag/weight = {:.3g}", c.advice.max_drag_to_weight); }

std::string linear_note(const TermContext& c) {
    const VariantAdvice& a = c.advice;
    if (a.re_max <= 1.0) return fmt::format("Re <= {:.2g}: Stokes flow", a.re_max);
    return fmt::format("Re up to {:.2g}: linear drag is wrong here by {:.0f}x in force", a.re_max, a.stokes_error_factor);
}

std::string quadratic_note(const TermContext& c) {
    return fmt::format("Cd = {:g}, Re = {:.2g} .. {:.2g}", candidate_drag(DragModel::quadratic, c.variant.drag).cd,
                       c.advice.re_min, c.advice.re_max);
}

// Archimedes: the buoyant force is rho_air / rho_particle of the weight, per particle.
std::string buoyancy_note(const TermContext& c) {
    const std::vector<double>& r = c.advice.density_ratio;
    if (r.empty()) return {};
    const auto [lo, hi] = std::minmax_element(r.begin(), r.end());
    std::string ratio = fmt::format("rho_air/rho_particle = {:.3g} (particle {})", *hi, hi - r.begin());
    if (*lo != *hi) ratio += fmt::format(" .. {:.3g} (particle {})", *lo, lo - r.begin());
    // Its effect on landing time and place, when the verdict does not list them already.
    for (AdviceMetric m : {AdviceMetric::landing_time, AdviceMetric::landing_point})
        if (!c.run.metric(m).beyond_tolerance) ratio += ", " + describe(m, c.run.metric(m));
    return ratio;
}

// The added mass is 1/2 rho V: half the density ratio, in units of the particle's own mass.
std::string added_mass_note(const TermContext& c) {
    const std::vector<double>& r = c.advice.density_ratio;
    if (r.empty()) return {};
    return fmt::format("added mass up to {:.3g} of the particle's mass", 0.5 * *std::max_element(r.begin(), r.end()));
}

// The ISA against constant air of the ISA's density and viscosity at the floor: what the thinning
// over the room's height changes, whatever air the variant has (the altitude itself is the
// base_altitude the user chose).
Air isa_of(const Air& air) {
    Air isa = air;
    isa.model = AirModel::isa;
    return isa;
}
bool isa_air(Model& m) { return set(m.world.air.model, AirModel::isa); }
bool air_at_floor(Model& m) {
    const Air floor = local_air(isa_of(m.world.air), m.room, m.room.floor_y());  // constant air
    const Air& now = m.world.air;
    if (now.model == AirModel::constant && now.density_kg_m3 == floor.density_kg_m3 && now.viscosity_pa_s == floor.viscosity_pa_s)
        return false;
    m.world.air = floor;
    return true;
}

// A constant air thinner than the ISA's anywhere in the troposphere (a vacuum) is not a standard
// day at any altitude: the ISA's thinning says nothing about it.
const char* isa_not_applicable(const Model& m, std::size_t) {
    if (m.world.air.model == AirModel::constant && m.world.air.density_kg_m3 < isa_density(max_base_altitude_m))
        return "the air is thinner than the ISA's anywhere in the troposphere";
    return nullptr;
}

std::string isa_note(const TermContext& c) {
    const Air air = isa_of(c.variant.world.air);
    const Room& room = c.variant.room;
    const double floor = air_density_at(air, altitude_in_room(air, room, room.floor_y()));
    const double ceiling = air_density_at(air, altitude_in_room(air, room, room.floor_y() + room.size.y));
    return fmt::format("ISA density {:.4g} kg/m^3 at the floor ({:g} m), {:.2g}% less at the ceiling", floor,
                       air.base_altitude_m, 100.0 * (1.0 - ceiling / floor));
}

const char* collisions_not_applicable(const Model&, std::size_t particles) {
    return particles < 2 ? "one particle: nothing to collide with" : nullptr;
}

// Collisions: the estimate (collision_estimate.hpp) and the measured runs each can say they
// matter; the verdict gives the estimate's reason and what the runs measured.
std::string collisions_verdict(const TermContext& c) {
    const CollisionEstimate& e = c.advice.collisions;
    const bool on = recommend_collisions(e, c.run.matters);
    std::string measured = "measured";
    if (e.measured_particles < e.particles)
        measured += fmt::format(" on the first {} of {} particles (fewer collisions than the whole scene)",
                                e.measured_particles, e.particles);
    measured += ": " + c.measured;
    const char* action = c.run.in_scene ? (on ? "keep them on" : "they could be turned off")
                                        : (on ? "turn them on" : "leave them off");
    if (e.matters) return fmt::format("collisions matter: {}; {}: {}", collision_reason(e), measured, action);
    if (on) return fmt::format("collisions matter: {}, although the estimate is {}: {}", measured, collision_reason(e), action);
    return fmt::format("collisions do not matter: {}; {}: {}", collision_reason(e), measured, action);
}

// The rows, in the order of the verdicts and of the JSON's "runs": first each drag model against
// the reference (the reference itself last, all zeros), then the toggles.
const std::array<TermRow, 10> rows = {{
    {"no drag", TermKind::alternative, [](const Model& m) { return m.drag.model == DragModel::none; },
     use_drag<DragModel::none>, use_reference_drag, nullptr, nullptr, false},
    {"linear drag", TermKind::alternative, [](const Model& m) { return m.drag.model == DragModel::linear; },
     use_drag<DragModel::linear>, use_reference_drag, nullptr, linear_note},
    {"quadratic drag", TermKind::alternative, [](const Model& m) { return m.drag.model == DragModel::quadratic; },
     use_drag<DragModel::quadratic>, use_reference_drag, nullptr, quadratic_note},
    {"sphere_re drag", TermKind::alternative, [](const Model& m) { return m.drag.model == DragModel::sphere_re; },
     use_reference_drag, use_reference_drag, nullptr, nullptr, false},
    {"drag", TermKind::toggle, [](const Model& m) { return m.drag.model != DragModel::none; }, drag_on,
     use_drag<DragModel::none>, nullptr, drag_note},
    {"buoyancy", TermKind::toggle, [](const Model& m) { return m.world.buoyancy; },
     [](Model& m) { return set(m.world.buoyancy, true); }, [](Model& m) { return set(m.world.buoyancy, false); },
     nullptr, buoyancy_note},
    {"added mass", TermKind::toggle, [](const Model& m) { return m.world.added_mass; },
     [](Model& m) { return set(m.world.added_mass, true); }, [](Model& m) { return set(m.world.added_mass, false); },
     nullptr, added_mass_note},
    {"ISA air (thinning with height)", TermKind::toggle, [](const Model& m) { return m.world.air.model == AirModel::isa; },
     isa_air, air_at_floor, isa_not_applicable, isa_note},
    {collisions_term, TermKind::toggle, [](const Model& m) { return m.collisions.enabled; },
     [](Model& m) { return set(m.collisions.enabled, true); }, [](Model& m) { return set(m.collisions.enabled, false); },
     collisions_not_applicable, nullptr, true, collisions_verdict},
    // Wind last: the runs of a scene with wind end with the calm run.
    {"wind", TermKind::toggle, [](const Model& m) { return m.world.wind.kind != WindKind::none; }, as_configured,
     [](Model& m) { return set(m.world.wind.kind, WindKind::none); }, wind_not_applicable, nullptr},
}};

}  // namespace

bool use_reference_drag(Model& m) { return use_drag<reference_drag>(m); }

std::span<const TermRow> term_table() { return rows; }

}  // namespace pl
