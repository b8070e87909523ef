// Narrow phase and response of two spheres: when their surfaces meet inside a step, and the
// impulse that separates them.
//
// Time of impact: over one step the relative motion is taken as linear, d(s) = d + w s (d: centre
// of b minus centre of a, w: their relative displacement rate), and the contact is the first root
// of |d + w s| = R = r_a + r_b, a quadratic in s.
//
// Impulse (Stronge, "Impact Mechanics", 2000, ch. 2-5; Mirtich, "Impulse-based dynamic simulation
// of rigid body systems", 1996): with n the unit normal from a to b and u the velocity of b's
// surface point at the contact minus a's (including the spin, w x r, where the spin takes part),
// the normal impulse is J_n = -(1 + e) u.n / (1/m_a + 1/m_b) (Newton's restitution law, e on the
// normal relative velocity); the tangential impulse opposes the sliding velocity u_t and is the
// smaller of the Coulomb bound mu J_n and the impulse that stops the sliding, |u_t| / K_t, with
// K_t = 1/m_a + 1/m_b (+ 1/(k_a m_a) + 1/(k_b m_b) with spin, I = k m r^2). Equal and opposite
// impulses keep the momentum; e = 1 without friction keeps the kinetic energy; friction that at
// most stops the sliding never adds energy.
#pragma once

#include "physics/model/scene.hpp"

#include <glm/geometric.hpp>

#include <cmath>

namespace pl::collide {

// The first s in [0, s_max] at which the gap closes to zero, or -1 if it does not. A pair that
// already touches or overlaps (|d| <= R) and is closing (d.w < 0) meets at s = 0.
inline double time_of_impact(const Vec3& d, const Vec3& w, double contact_distance, double s_max) {
    const double closing = glm::dot(d, w);  // < 0: the centres approach
    if (!(closing < 0.0)) return -1.0;
    const double c = glm::dot(d, d) - contact_distance * contact_distance;
    if (c <= 0.0) return 0.0;
    const double a = glm::dot(w, w);
    const double disc = closing * closing - a * c;
    if (disc < 0.0) return -1.0;  // the paths pass by
    // The smaller root of a s^2 + 2 closing s + c = 0, in the form without cancellation (closing < 0).
    const double s = c / (-closing + std::sqrt(disc));
    return s <= s_max ? s : -1.0;
}

// One sphere as the impulse sees it. With added mass (world.added_mass) `mass` is the inertial
// mass M = m + 1/2 rho V: the fluid the sphere carries along is struck with it. The moment keeps
// k m r^2: a sphere turning in an ideal fluid sets none of it moving (no added moment of
// inertia; Lamb, Hydrodynamics, 1932, sec. 92).
struct Body {
    Vec3 velocity;
    Vec3 spin;  // rad/s; used only when the spin takes part
    double mass = 1.0;
    double radius = 1.0;
    double moment = 0.4;  // I = k m r^2, kg m^2
};

// The changes of velocity and spin of a and b, and the impulse on b (a gets its opposite).
struct ImpulseResult {
    Vec3 dv_a{0.0}, dv_b{0.0}, dw_a{0.0}, dw_b{0.0};
    Vec3 impulse{0.0};
    bool applied = false;  // false: the contact point was not closing, nothing changes
};

// Surface velocity of b minus a's at the contact point (n from a to b).
inline Vec3 contact_velocity(const Body& a, const Body& b, const Vec3& n, bool with_spin) {
    Vec3 u = b.velocity - a.velocity;
    if (with_spin) u += glm::cross(b.spin, -b.radius * n) - glm::cross(a.spin, a.radius * n);
    return u;
}

inline ImpulseResult sphere_impulse(const Body& a, const Body& b, const Vec3& n, double restitution, double friction,
                                    bool with_spin) {
    ImpulseResult r;
    const Vec3 u = contact_velocity(a, b, n, with_spin);
    const double un = glm::dot(u, n);
    if (!(un < 0.0)) return r;
    const double inv_a = 1.0 / a.mass, inv_b = 1.0 / b.mass;
    const double jn = -(1.0 + restitution) * un / (inv_a + inv_b);
    r.impulse = jn * n;
    const Vec3 ut = u - un * n;
    const double slide = glm::length(ut);
    if (friction > 0.0 && slide > 0.0) {
        double k_t = inv_a + inv_b;
        if (with_spin) k_t += a.radius * a.radius / a.moment + b.radius * b.radius / b.moment;
        const double jt = std::min(friction * jn, slide / k_t);
        r.impulse -= (jt / slide) * ut;
    }
    r.dv_a = -inv_a * r.impulse;
    r.dv_b = inv_b * r.impulse;
    if (with_spin) {
        // Angular impulse r x P about each centre: a's contact point is at +r_a n, b's at -r_b n.
        r.dw_a = glm::cross(a.radius * n, -r.impulse) / a.moment;
        r.dw_b = glm::cross(-b.radius * n, r.impulse) / b.moment;
    }
    r.applied = true;
    return r;
}

}  // namespace pl::collide
