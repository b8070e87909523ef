// Rows of one entry of the preset's "expect" list: a compare metric worth watching and its
// expected value (see physics/model/expectation.hpp).
#pragma once

#include "physics/model/field_schema.hpp"
#include "physics/model/schema/limits.hpp"

namespace pl::schema {

inline constexpr Field<Expectation> expectation_rows[] = {
    enumeration<Expectation, &Expectation::quantity>("quantity", quantity_count, "quantity",
                                                     "A compare metric, named as `particle-lab compare --json` names it.")
        .required(),
    number("value", &Expectation::value, "", any_finite(), "expected",
           "The expected value, in the quantity's unit (the suffix of its name).")
        .required(),
    number("tolerance", &Expectation::tolerance, "", non_negative(max_expectation_tolerance), "tolerance",
           "Met when |measured - value| <= tolerance (same unit as value)."),
    unsigned_integer("particle", &Expectation::particle, max_particles, "particle",
                     "Which particle: an index into the listed particles, then the emitted ones."),
    unsigned_integer("variant", &Expectation::variant, max_particles, "variant",
                     "Which variant: an index into \"variants\" (0 when the scene has none)."),
};

template <>
struct SectionSchema<Expectation> : NoChildren {
    static constexpr const char* name = "expectation";
    static constexpr std::span<const Field<Expectation>> rows = expectation_rows;
};

}  // namespace pl::schema
