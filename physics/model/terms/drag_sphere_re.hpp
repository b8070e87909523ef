// Smooth-sphere drag over the whole Re range: a = -k (Cd Re)(Re) u, k = pi R mu / (4 m),
// Re = re_scale |u| (Morrison's correlation, drag.hpp). Power into the drag ledger; stiffness
// d|a|/du by a relative finite difference.
// schema rows: see physics/model/schema/ (drag.model = sphere_re)
#pragma once

#include "physics/model/terms/term.hpp"

#include <algorithm>
#include <cmath>

namespace pl::terms {

struct DragSphereRe : DragBase<DragModel::sphere_re> {
    // The rest test runs the slide once for all particles; the correlation's pow at Re = 0 is
    // not worth proving uniform, so particles at rest take the per-particle path.
    static constexpr bool rest_is_uniform = false;

    double rate(const Vec3& u) const { return drag.k * sphere_cd_times_re(drag.re_scale * std::sqrt(glm::dot(u, u))); }
    // d/du of k CdRe(Re) u, estimated with a relative finite difference (at least k CdRe).
    static double stiffness(double k, double re_scale, double u) {
        const double re = re_scale * u;
        const double f0 = sphere_cd_times_re(re) * u;
        const double du = 1e-6 * (u + 1e-9);
        const double f1 = sphere_cd_times_re(re_scale * (u + du)) * (u + du);
        return k * std::max((f1 - f0) / du, sphere_cd_times_re(re));
    }
};

}  // namespace pl::terms
