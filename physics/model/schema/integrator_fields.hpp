// Rows of the preset's "integrator" section (see physics/model/field_schema.hpp).
#pragma once

#include "physics/model/field_schema.hpp"
#include "physics/model/schema/limits.hpp"

namespace pl::schema {

inline constexpr Field<IntegratorSettings> integrator_rows[] = {
    enumeration<IntegratorSettings, &IntegratorSettings::method>(
        "method", 6, "method",
        "explicit_euler, semi_implicit_euler (symplectic, the classic default), velocity_verlet, rk4, dopri5 "
        "(adaptive Dormand-Prince 5(4)) or exponential (drag-exact)."),
    number("dt", &IntegratorSettings::dt, "s", positive(max_dt_s), "dt", "The fixed step every run advances by."),
    number("rtol", &IntegratorSettings::rtol, "", positive(max_tolerance), "rtol", "dopri5: relative error tolerance.")
        .when(bit<Method::dopri5>()),
    number("atol", &IntegratorSettings::atol, "", positive(max_tolerance), "atol",
           "dopri5: absolute error tolerance (m, m/s).")
        .when(bit<Method::dopri5>()),
    boolean("adaptive", &IntegratorSettings::adaptive, "adaptive (error control)",
            "dopri5: error-controlled substeps within each dt; false takes exactly one Dormand-Prince step per dt.")
        .when(bit<Method::dopri5>()),
};

template <>
struct SectionSchema<IntegratorSettings> : NoChildren {
    static constexpr const char* name = "integrator";
    static constexpr std::span<const Field<IntegratorSettings>> rows = integrator_rows;
};

}  // namespace pl::schema
