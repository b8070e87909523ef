#include "physics/stepping/warnings.hpp"

#include "physics/model/drag.hpp"

#include <fmt/format.h>

#include <glm/geometric.hpp>

#include <limits>

namespace pl {

double no_rest_dt(const Model& model) {
    const double e = model.contact.restitution, g = glm::length(model.world.gravity);
    if (model.integrator.method != Method::explicit_euler || !(e > 0.0 && e < 1.0) || !(g > 0.0))
        return std::numeric_limits<double>::infinity();
    return model.contact.rest_speed * (1.0 - e) / (e * g);
}

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
        case WarningKind::runaway:
            return fmt::format("particle {} frozen at t = {:.6g} s: its speed reached {:.3g} m/s, beyond the speed of "
                               "light (a numerical blow-up); last state kept",
                               w.particle, w.t, w.value);
        case WarningKind::impact_cap:
            return fmt::format("particle {} frozen at t = {:.6g} s: more than {} wall impacts in one step (speed "
                               "{:.3g} m/s); last state kept",
                               w.particle, w.t, max_impacts_per_step, w.value);
        case WarningKind::no_rest:
            return fmt::format("particle {}: explicit Euler cannot come to rest at dt = {:.3g} s (it gains speed on "
                               "every bounce arc, so its rebounds never fall below rest_speed): use dt <= {:.3g} s "
                               "= rest_speed (1 - e) / (e g), or another method",
                               w.particle, model.integrator.dt, w.value);
        case WarningKind::collision_overlap:
            return fmt::format("particle {} ended the step at t = {:.6g} s inside another ball by {:.0f}% of their "
                               "contact distance: the collision pass could not keep them apart within one step (it meets "
                               "pairs on straight paths from a step's start to its end, which a ball that struck a wall "
                               "on the way did not follow, and a crowd struck hard in one step asks more of the contact "
                               "solver's iterations than they give). Use a smaller dt (dt = {:.3g} s now), so that balls move less than their radius a step",
                               w.particle, w.t, 100.0 * w.value, model.integrator.dt);
        case WarningKind::collision_crossing:
            return fmt::format("particle {} and another ball crossed each other within the step ending at t = {:.6g} s: "
                               "their separation moved {:.3g} contact distances in one step, too far for the collision "
                               "pass to follow (it meets pairs on straight paths, and a ball that struck a wall or was "
                               "driven against one on the way did not take one), so they may have gone through each "
                               "other. Use a smaller dt (dt = {:.3g} s now), so that balls move less than their radius a step",
                               w.particle, w.t, w.value, model.integrator.dt);
    }
    return {};
}

}  // namespace pl
