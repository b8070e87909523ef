// Rows of one entry of the preset's "particles" list (see physics/model/field_schema.hpp).
#pragma once

#include "physics/model/field_schema.hpp"
#include "physics/model/schema/limits.hpp"

namespace pl::schema {

inline constexpr Field<ParticleSpec> particle_rows[] = {
    vec3("position", &ParticleSpec::position, "m", any_finite(), "position",
         "Centre of the sphere; it must lie a radius away from every wall.")
        .required(),
    bounded_vec3("velocity", &ParticleSpec::velocity, "m/s", max_speed_mps, "velocity", "Initial velocity."),
    number("mass", &ParticleSpec::mass, "kg", at_least(min_mass_kg, max_mass_kg), "mass", "0.057 kg: a tennis ball."),
    number("radius", &ParticleSpec::radius, "m", positive(max_room_size_m), "radius",
           "Less than half the room's smallest size."),
    bounded_vec3("spin", &ParticleSpec::spin, "rad/s", max_spin_rad_s, "spin",
                 "Angular velocity (right-hand rule); it acts with drag.lift or contact.spin."),
    enumeration<ParticleSpec, &ParticleSpec::inertia>(
        "inertia", 2, "inertia", "Moment of inertia: solid (2/5 m R^2) or hollow, a thin shell (2/3 m R^2)."),
};

template <>
struct SectionSchema<ParticleSpec> : NoChildren {
    static constexpr const char* name = "particle";
    static constexpr std::span<const Field<ParticleSpec>> rows = particle_rows;
};

}  // namespace pl::schema
