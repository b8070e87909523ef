// Wall contact with spin (contact.spin): friction acts at the contact point, so it changes the
// spin as well as the velocity. A rigid sphere of radius R, inertia I = k m R^2, touching a wall
// with inward normal n at the point -R n slips there at
//   s = v_t - R (w x n)          (v_t: the velocity along the wall).
// A tangential impulse J (per kg) at that point changes v_t by J and w by -(n x J) / (k R), so the
// slip by J (1 + 1/k): the impulse that ends the slip is J = -s k / (1 + k).
//  * Impact (Stronge, "Impact Mechanics", 2000, ch. 5; Cross, "Grip-slip behavior of a bouncing
//    ball", Am. J. Phys. 70, 1093 (2002)): Newton's restitution on the normal velocity, and the
//    Coulomb impulse |J| <= mu (1 + e) |v_n| against the slip, capped where the slip would
//    reverse: then the ball leaves rolling (grip; no tangential rebound, Cross's e_x = 0). With
//    grip, v_t' = (v_t + k R (w x n)) / (1 + k): a solid ball's (5 v_t + 2 R w) / 7.
//  * Resting on one wall: while it slips, the friction -mu N s_hat decelerates v and spins w up,
//    so the slip falls at mu N (1 + 1/k) and the ball rolls after t = |s0| k / ((1 + k) mu N): a
//    ball sliding at v0 without spin rolls at v0 / (1 + k) (5/7 solid, 3/5 hollow) after sliding
//    2 v0 / (7 mu g) (solid) over 12 v0^2 / (49 mu g). While it rolls, a tangential force a_t
//    accelerates it at a_t / (1 + k) (static friction holds the roll while k |a_t| / (1 + k) <=
//    mu N), and rolling resistance decelerates it at c_rr N: it stops after v^2 / (2 c_rr g) on a
//    level floor, and stays stopped while |a_t| / (1 + k) <= c_rr N. The forces at the step's
//    start are held over the step and each phase (slide, roll, stop) is solved exactly, the
//    switching times inside the step included: exact on a level floor without drag.
// The spin's decay in flight (terms/magnus.hpp) is dissipated by the air: the drag ledger line.
// Not modelled: spin about the normal (it is kept, unchanged), spin decay while in contact, and
// spin in corners (resting on two walls at once: the point-mass slide runs, the spin is kept).
#pragma once

#include "physics/model/terms/magnus.hpp"
#include "physics/stepping/contact.hpp"
#include "physics/stepping/events.hpp"

#include <bit>
#include <vector>

namespace pl {

// Rotational kinetic energy per kg, 1/2 k R^2 |w|^2.
inline double spin_energy_per_kg(double k, double radius, const Vec3& w) {
    return 0.5 * k * radius * radius * glm::dot(w, w);
}

// A particle's rotation while it is stepped.
struct SpinStep {
    SpinClock clock;             // the spin, as a function of time
    double inertia = 0.4;        // k in I = k m R^2
    double rolling_loss = 0.0;   // per kg, to rolling resistance during this step
    double decay_loss = 0.0;     // per kg, to the air's torque (the spin decay) during this step

    // The spin at t, with the clock restarted there: the energy the decay took since the clock's
    // last start goes to decay_loss (exact: the decay is in closed form).
    Vec3 restart(double t, double radius) {
        const Vec3 w = clock.at(t);
        decay_loss += spin_energy_per_kg(inertia, radius, clock.omega) - spin_energy_per_kg(inertia, radius, w);
        clock.omega = w;
        clock.since = t;
        return w;
    }
};

// The spin of a ball rolling at v_t on the wall with normal n (its spin about n kept).
inline Vec3 rolling_spin(const Vec3& w, const Vec3& v_t, const Vec3& n, double radius) {
    return glm::dot(w, n) * n + glm::cross(n, v_t) / radius;
}

// The impact at time t with the friction coupled to the spin (file comment); updates the spin.
inline ImpactResult spin_impact(const Vec3& v, SpinStep& spin, const Vec3& n, double radius,
                                const ContactSettings& c, double t) {
    ImpactResult r;
    const Vec3 w = spin.restart(t, radius);
    const double k = spin.inertia;
    const double vn = glm::dot(v, n);
    r.normal_speed_in = vn < 0.0 ? -vn : 0.0;
    r.normal_speed_out = c.restitution * r.normal_speed_in;
    const Vec3 vt = v - vn * n;
    const Vec3 slip = vt - radius * glm::cross(w, n);
    const double slip_len = glm::length(slip);
    Vec3 vt_out = vt, w_out = w;
    if (slip_len > 0.0) {
        const double limit = c.friction * (1.0 + c.restitution) * r.normal_speed_in;
        const double grip = slip_len * k / (1.0 + k);
        const Vec3 j = -(std::min(limit, grip) / slip_len) * slip;
        vt_out = vt + j;
        w_out = grip <= limit ? rolling_spin(w, vt_out, n, radius) : w - glm::cross(n, j) / (k * radius);
    }
    r.v_out = vt_out + r.normal_speed_out * n;
    r.bounce_loss_per_kg = 0.5 * (r.normal_speed_in * r.normal_speed_in - r.normal_speed_out * r.normal_speed_out);
    r.friction_loss_per_kg = 0.5 * glm::dot(vt, vt) + spin_energy_per_kg(k, radius, w) -
                             (0.5 * glm::dot(vt_out, vt_out) + spin_energy_per_kg(k, radius, w_out));
    spin.clock.omega = w_out;
    return r;
}

// One phase of resting contact: constant accelerations over tau.
struct ContactPhase {
    double tau = 0.0;
    Vec3 a{0.0};       // of the centre
    Vec3 w_end{0.0};   // the spin at its end
    bool ends = false;  // a switch (slip ends, roll stops) ends it before the step does
};

// The slip at the contact point; zero where it is round-off of a roll (a rolling ball's spin
// is set from its velocity, rolling_spin, which leaves a slip of a few ulps).
inline Vec3 contact_slip(const Vec3& v, const Vec3& w, const Vec3& n, double radius) {
    const Vec3 spin_speed = radius * glm::cross(w, n);
    const Vec3 slip = v - spin_speed;
    return glm::length(slip) > 1e-12 * (glm::length(v) + glm::length(spin_speed)) ? slip : Vec3(0.0);
}

// Slipping on the wall (or starting to, where static friction cannot hold a roll).
inline ContactPhase slip_phase(const Vec3& v, const Vec3& w, const Vec3& slip, const Vec3& n, const Vec3& a_t,
                               double press, double k, double radius, double mu, double left) {
    ContactPhase ph;
    const double slip_len = glm::length(slip);
    const Vec3 dir = slip_len > 0.0 ? slip / slip_len : a_t / glm::length(a_t);
    const Vec3 a_f = -(mu * press) * dir;
    ph.a = a_t + a_f;
    const double closing = mu * press * (1.0 + 1.0 / k) - glm::dot(a_t, dir);  // d|s|/dt = -closing
    ph.ends = closing > 0.0 && slip_len < closing * left;
    ph.tau = ph.ends ? slip_len / closing : left;
    const Vec3 v_end = v + ph.tau * ph.a;
    ph.w_end = ph.ends ? rolling_spin(w, v_end, n, radius) : w - (ph.tau / (k * radius)) * glm::cross(n, a_f);
    return ph;
}

// Rolling (or starting to roll from rest), slowed by rolling resistance c_rr N.
inline ContactPhase roll_phase(const Vec3& v, const Vec3& w, const Vec3& n, const Vec3& a_t, double press,
                               double k, double radius, double c_rr, double left) {
    ContactPhase ph;
    const double speed = glm::length(v);
    const Vec3 dir = speed > 0.0 ? v / speed : a_t / glm::length(a_t);
    ph.a = a_t / (1.0 + k) - (c_rr * press) * dir;
    const double closing = c_rr * press - glm::dot(a_t, dir) / (1.0 + k);  // d|v|/dt = -closing
    ph.ends = speed > 0.0 && closing > 0.0 && speed < closing * left;
    ph.tau = ph.ends ? speed / closing : left;
    ph.w_end = rolling_spin(w, ph.ends ? Vec3(0.0) : v + ph.tau * ph.a, n, radius);
    return ph;
}

// Resting contact with spin on one wall for a step of length h from t, under the forces d at the
// step's start (file comment). Returns false where it does not apply (resting on several walls).
// `hit_wall(wall, t)` answers a wall met on the way.
template <class P, class HitWall>
bool spin_slide(P& p, const RoomBounds& room, const ContactSettings& c, double t, double h, const Derivative& d,
                std::vector<Event>* events, std::uint32_t id, HitWall&& hit_wall) {
    if (std::popcount(p.resting) != 1) return false;
    const int wall = std::countr_zero(p.resting);
    const Vec3 n = RoomBounds::inward_normal(wall);
    const double press = -glm::dot(d.a, n);
    const Vec3 a_t = d.a + press * n;
    const double k = p.spin.inertia, r = p.radius;
    const Vec3 x0 = p.y.x;
    Vec3 v = p.y.v - glm::dot(p.y.v, n) * n;
    Vec3 w = p.spin.restart(t, r);
    double done = 0.0;
    for (int phase = 0; phase < 4 && done < h; ++phase) {
        const double at_len = glm::length(a_t);
        const Vec3 slip = contact_slip(v, w, n, r);
        const bool slipping = slip != Vec3(0.0) || k * at_len > (1.0 + k) * c.friction * press;
        if (!slipping && v == Vec3(0.0) && at_len <= (1.0 + k) * c.rolling_resistance * press) break;  // held
        const ContactPhase ph = slipping ? slip_phase(v, w, slip, n, a_t, press, k, r, c.friction, h - done)
                                         : roll_phase(v, w, n, a_t, press, k, r, c.rolling_resistance, h - done);
        const Vec3 dx = ph.tau * v + (0.5 * ph.tau * ph.tau) * ph.a;
        const Vec3 v_end = !slipping && ph.ends ? Vec3(0.0) : v + ph.tau * ph.a;
        // What the tangential forces gave and the motion did not keep went to the contact.
        const double loss = 0.5 * glm::dot(v, v) + spin_energy_per_kg(k, r, w) + glm::dot(a_t, dx) -
                            (0.5 * glm::dot(v_end, v_end) + spin_energy_per_kg(k, r, ph.w_end));
        (slipping ? p.friction_loss : p.spin.rolling_loss) += loss;
        if (!slipping && ph.ends) events->push_back({t + done + ph.tau, id, -1, EventKind::stop, glm::length(v), 0.0});
        p.y.x += dx;
        v = v_end;
        w = ph.w_end;
        done += ph.tau;
    }
    p.y.v = v;
    p.y.drag_loss += h * d.drag_power;
    p.y.wind_gain += h * d.wind_power;
    p.spin.clock.omega = w;  // no decay while in contact
    p.spin.clock.since = t + h;
    // Another wall met on the way: found along the chord, answered there, the rest in a straight line.
    const Vec3 x1 = p.y.x;
    int hit = -1;
    double frac = 1.0;
    for (int o = 0; o < wall_count; ++o) {
        const double d_end = room.distance(o, x1, r);
        if (o == wall || d_end >= 0.0) continue;
        const double d0 = std::max(0.0, room.distance(o, x0, r));
        const double f = d0 / (d0 - d_end);
        if (hit < 0 || f < frac) { hit = o; frac = f; }
    }
    if (hit >= 0) {
        p.y.x = x0 + frac * (x1 - x0);
        p.y.x[RoomBounds::axis(hit)] = room.contact_plane(hit, r);
        p.spin.clock.since = t + frac * h;
        hit_wall(hit, t + frac * h);
        p.spin.clock.since = t + h;
        p.y.x += (1.0 - frac) * h * p.y.v;
    }
    p.y.x = room.clamp_inside(p.y.x, r);
    p.y.x[RoomBounds::axis(wall)] = room.contact_plane(wall, r);
    return true;
}

}  // namespace pl
