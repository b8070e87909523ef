#include "physics/stepping/warnings.hpp"

#include "physics/model/drag.hpp"

#include <fmt/format.h>

namespace pl {

std::string warning_message(const Warning& w, const Model& model) {
    switch (w.kind) {
        case WarningKind::drag_validity: {
            const ReRange valid = drag_validity(model.drag.model);
            return fmt::format("particle {}: Re = {:.3g} at t = {:.3f} s is outside the {} drag model's validity range "
                               "{:.3g} < Re < {:.3g}",
                               w.particle, w.value, w.t, to_string(model.drag.model), valid.lo, valid.hi);
        }
        case WarningKind::mach:
            return fmt::format("particle {}: Mach {:.2f} at t = {:.3f} s; compressibility is not modelled (results "
                               "unreliable above Mach 0.3)",
                               w.particle, w.value / speed_of_sound_mps, w.t);
        case WarningKind::stability: {
            const double k = w.value, dt = model.integrator.dt;
            const double limit = method_stability_limit(model.integrator.method);
            return fmt::format("particle {}: dt * k = {:.3g} exceeds the {} stability limit {:.3g} (drag stiffness k "
                               "= {:.3g} 1/s); use dt <= {:.3g} s or the exponential method",
                               w.particle, k * dt, to_string(model.integrator.method), limit, k, 0.9 * limit / k);
        }
        case WarningKind::frozen:
            return fmt::format("particle {} frozen at t = {:.6g} s: its state became non-finite (NaN/Inf) during the "
                               "step; last finite state kept",
                               w.particle, w.t);
    }
    return {};
}

}  // namespace pl
