// Rows of the preset's "contact" section (see physics/model/field_schema.hpp).
#pragma once

#include "physics/model/field_schema.hpp"
#include "physics/model/schema/limits.hpp"

namespace pl::schema {

inline constexpr Field<ContactSettings> contact_rows[] = {
    number("restitution", &ContactSettings::restitution, "", closed(0.0, 1.0), "restitution e",
           "Normal rebound speed / impact speed, 0 (sticks) .. 1 (no loss)."),
    number("friction", &ContactSettings::friction, "", non_negative(max_friction), "friction mu",
           "Coulomb friction coefficient on the walls."),
    number("rest_speed", &ContactSettings::rest_speed, "m/s", non_negative(max_rest_speed_mps), "rest speed",
           "A rebound slower than this ends in rest on the wall."),
    boolean("spin", &ContactSettings::spin, "friction spins the ball",
            "true: friction acts at the contact point and couples to the spin (a sliding ball ends up rolling "
            "at 5/7 of its speed, solid); false: point-mass friction, the spin is left alone."),
    number("rolling_resistance", &ContactSettings::rolling_resistance, "", non_negative(max_friction),
           "rolling resistance c_rr",
           "With spin: a rolling ball decelerates at c_rr g (stops after v^2 / (2 c_rr g)); about 0.001 to 0.02."),
    enumeration<ContactSettings, &ContactSettings::restitution_law>(
        "restitution_law", 2, "restitution law",
        "constant: e = restitution. viscoelastic: e(v) = 1 - (1 - restitution) (v / restitution_speed)^(1/5) "
        "(Ramirez et al. 1999): faster impacts lose more."),
    number("restitution_speed", &ContactSettings::restitution_speed, "m/s", positive(max_speed_mps),
           "restitution speed", "viscoelastic: the impact speed at which e equals restitution."),
};

template <>
struct SectionSchema<ContactSettings> : NoChildren {
    static constexpr const char* name = "contact";
    static constexpr std::span<const Field<ContactSettings>> rows = contact_rows;
};

}  // namespace pl::schema
