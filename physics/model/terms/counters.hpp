// Evaluation counters: one per force term (a term names its slot, Term::counter) and the
// stepping counts. The counter tests prove that a disabled term is never evaluated.
#pragma once

#include <cstdint>

namespace pl {

struct ForceCounters {
    std::uint64_t gravity = 0, drag = 0, wind = 0, buoyancy = 0, magnus = 0;  // one count per particle per evaluation
    std::uint64_t air_column = 0;      // evaluations through the air column (terms/air_column.hpp)
    std::uint64_t rejected_steps = 0;  // dopri5 only
    std::uint64_t accepted_steps = 0;  // dopri5 internal steps
    std::uint64_t contacts = 0;        // time-of-impact solves
    std::uint64_t fast_path = 0;       // particle-steps the vectorised fast path finished

    ForceCounters& operator+=(const ForceCounters& o) {
        gravity += o.gravity;
        drag += o.drag;
        wind += o.wind;
        buoyancy += o.buoyancy;
        magnus += o.magnus;
        air_column += o.air_column;
        rejected_steps += o.rejected_steps;
        accepted_steps += o.accepted_steps;
        contacts += o.contacts;
        fast_path += o.fast_path;
        return *this;
    }
};

}  // namespace pl
