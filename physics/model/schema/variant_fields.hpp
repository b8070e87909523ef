// Rows of one entry of the preset's "variants" list. Each overridden section starts from the
// scene's own (the third argument of `visit` finds it), so a variant need only name what differs.
#pragma once

#include "physics/model/field_schema.hpp"
#include "physics/model/schema/collision_fields.hpp"
#include "physics/model/schema/contact_fields.hpp"
#include "physics/model/schema/drag_fields.hpp"
#include "physics/model/schema/integrator_fields.hpp"
#include "physics/model/schema/world_fields.hpp"

namespace pl::schema {

inline constexpr Field<Variant> variant_rows[] = {
    string("label", &Variant::label, "label", "The variant's name in plots and tables: not empty, unique.")
        .required()
        .non_empty(),
};

template <>
struct SectionSchema<Variant> {
    static constexpr const char* name = "variant";
    static constexpr std::span<const Field<Variant>> rows = variant_rows;
    template <class V>
    static void children(V&& visit) {
        visit(ChildInfo{"drag", "Overrides the scene's drag section."}, &Variant::drag,
              [](const Scene& s) -> const DragSettings& { return s.drag; });
        visit(ChildInfo{"wind", "Overrides the scene's world.wind section."}, &Variant::wind,
              [](const Scene& s) -> const WindSettings& { return s.world.wind; });
        visit(ChildInfo{"air", "Overrides the scene's world.air section."}, &Variant::air,
              [](const Scene& s) -> const Air& { return s.world.air; });
        visit(ChildInfo{"contact", "Overrides the scene's contact section."}, &Variant::contact,
              [](const Scene& s) -> const ContactSettings& { return s.contact; });
        visit(ChildInfo{"collisions", "Overrides the scene's collisions section."}, &Variant::collisions,
              [](const Scene& s) -> const CollisionSettings& { return s.collisions; });
        visit(ChildInfo{"integrator", "Overrides the scene's integrator section."}, &Variant::integrator,
              [](const Scene& s) -> const IntegratorSettings& { return s.integrator; });
    }
};

}  // namespace pl::schema
