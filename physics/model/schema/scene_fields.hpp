// The preset document: its top-level rows and sections, and every section's header. Include
// this one header to iterate the whole format (see physics/model/field_schema.hpp).
#pragma once

#include "physics/model/field_schema.hpp"
#include "physics/model/schema/collision_fields.hpp"
#include "physics/model/schema/contact_fields.hpp"
#include "physics/model/schema/drag_fields.hpp"
#include "physics/model/schema/emitter_fields.hpp"
#include "physics/model/schema/expectation_fields.hpp"
#include "physics/model/schema/integrator_fields.hpp"
#include "physics/model/schema/particle_fields.hpp"
#include "physics/model/schema/room_fields.hpp"
#include "physics/model/schema/variant_fields.hpp"
#include "physics/model/schema/world_fields.hpp"

namespace pl::schema {

inline constexpr const char* preset_format_name = "particle-lab-preset";
inline constexpr int preset_format_version = 1;

inline constexpr Field<Scene> scene_rows[] = {
    tag<Scene>("format", FieldKind::format_tag, "Always \"particle-lab-preset\"."),
    tag<Scene>("version", FieldKind::version_tag, "The format's version: 1."),
    string("name", &Scene::name, "name", "The scene's title."),
    string("description", &Scene::description, "description", "What the experiment shows."),
};

template <>
struct SectionSchema<Scene> {
    static constexpr const char* name = "preset";
    static constexpr std::span<const Field<Scene>> rows = scene_rows;
    template <class V>
    static void children(V&& visit) {
        visit(ChildInfo{"room", "The axis-aligned box the particles bounce in.", true}, &Scene::room);
        visit(ChildInfo{"world", "Gravity, air and wind."}, &Scene::world);
        visit(ChildInfo{"drag", "Air resistance."}, &Scene::drag);
        visit(ChildInfo{"contact", "How particles bounce on and slide along the walls."}, &Scene::contact);
        visit(ChildInfo{"collisions", "Whether and how particles bounce off each other."}, &Scene::collisions);
        visit(ChildInfo{"integrator", "The numerical method and its fixed step."}, &Scene::integrator);
        visit(ChildInfo{"particles", "Particles listed one by one.", false, "particle"}, &Scene::particles);
        visit(ChildInfo{"emitter", "Many seeded particles (in addition to the list)."}, &Scene::emitter);
        visit(ChildInfo{"variants",
                        "Each overrides whole sections and runs in lockstep with the others from the same particles.",
                        false, "variant"},
              &Scene::variants);
        visit(ChildInfo{"expect",
                        "Quantities worth watching with their expected values; `compare --json` and the GUI show "
                        "measured beside expected.",
                        false, "expectation"},
              &Scene::expect);
    }
};

}  // namespace pl::schema
