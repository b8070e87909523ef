// Restitution as a function of the impact speed v_n (contact.restitution_law).
//   constant:     e = contact.restitution.
//   viscoelastic: e(v) = 1 - (1 - e_ref) (v / v_ref)^(1/5), the leading order of the law for
//                 viscoelastic spheres in Hertzian contact (Ramirez, Poschel, Brilliantov &
//                 Schwager, "Coefficient of restitution of colliding viscoelastic spheres",
//                 Phys. Rev. E 60, 4465 (1999): e = 1 - C1 A a^(2/5) v^(1/5) + C2 A^2 a^(4/5) v^(2/5)
//                 - ...), with the material constant C1 A a^(2/5) set by e_ref = contact.restitution
//                 at v_ref = contact.restitution_speed. The series is valid while 1 - e is small
//                 (about e > 0.7); e is clamped to [0, 1] where the leading order leaves it.
// The viscoelastic e rises towards 1 as the impacts slow down, so it does not end the bounce
// sequence by itself: v_(n+1) = v_n - c v_n^(6/5) falls as n^-5, the bounce times (2 v_n / g)
// still sum to a finite time, and infinitely many ever smaller bounces fill it, as with a
// constant e. The rest threshold (contact.rest_speed) still ends that tail.
#pragma once

#include "physics/model/scene.hpp"

#include <algorithm>
#include <cmath>

namespace pl {

inline double restitution_at(const ContactSettings& c, double impact_speed) {
    if (c.restitution_law == RestitutionLaw::constant) return c.restitution;
    const double e = 1.0 - (1.0 - c.restitution) * std::pow(impact_speed / c.restitution_speed, 0.2);
    return std::clamp(e, 0.0, 1.0);
}

// The contact settings for one impact at normal speed `impact_speed` (e from the law).
inline ContactSettings at_impact_speed(const ContactSettings& c, double impact_speed) {
    ContactSettings out = c;
    out.restitution = restitution_at(c, impact_speed);
    return out;
}

}  // namespace pl
