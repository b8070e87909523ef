// What a simulation warns about, once per particle and kind. A big scene can raise a warning
// for most of its particles, so a warning keeps only the number it reports (24 bytes); its text
// is made when something shows it.
#pragma once

#include "physics/model/scene.hpp"

#include <cstdint>
#include <string>

namespace pl {

enum class WarningKind : std::uint8_t {
    drag_validity,  // Re outside the drag model's validity range
    stability,      // dt * drag stiffness beyond the method's limit
    frozen,         // state became non-finite
    mach,           // relative speed above Mach 0.3: compressibility not modelled
};

struct Warning {
    WarningKind kind;
    std::uint32_t particle;
    double t;  // s: the step (frozen) or the monitor's sample (the others) that saw it
    // drag_validity: Re; mach: speed relative to the air (m/s); stability: drag stiffness k
    // (1/s); frozen: unused.
    double value = 0.0;
};

// The text for the user; the limits it quotes come from the model the warning was raised under.
std::string warning_message(const Warning& w, const Model& model);

}  // namespace pl
