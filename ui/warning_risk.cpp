#include "ui/warning_risk.hpp"

#include "physics/model/drag.hpp"

#include <glm/geometric.hpp>

#include <cmath>
#include <limits>

namespace pl::ui {
double drag_error_fraction(const Warning& w, const Simulation& sim) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    const Model& m = sim.model();
    const ParticleState& st = sim.state();
    if (w.particle >= st.size() || m.drag.model == DragModel::none) return inf;
    if (w.value > drag_validity(DragModel::sphere_re).hi) return inf;  // beyond the reference's data
    const DragCoefficients used = drag_coefficients(m.drag, m.world.air, st.mass[w.particle], st.radius[w.particle]);
    DragSettings sphere;
    sphere.model = DragModel::sphere_re;
    const DragCoefficients reference = drag_coefficients(sphere, m.world.air, st.mass[w.particle], st.radius[w.particle]);
    if (!(used.re_scale > 0.0)) return inf;
    const double u = w.value / used.re_scale;  // the relative speed at which the Re was seen
    const double a_used = drag_rate(m.drag.model, used, u) * u;
    const double a_reference = drag_rate(DragModel::sphere_re, reference, u) * u;
    const double scale = std::max(glm::length(m.world.gravity), a_reference);
    return scale > 0.0 ? std::abs(a_used - a_reference) / scale : inf;
}

bool puts_number_at_risk(const Warning& w, const Simulation& sim) {
    if (w.kind != WarningKind::drag_validity) return true;
    return !(drag_error_fraction(w, sim) <= negligible_drag_error);
}

}  // namespace pl::ui
