// One particle's step as the steppers see it: its working state (ParticleStep, StepContext), how
// it is loaded from and stored to the state arrays or frozen, and the closed-form pieces of wall
// contact (the first contact root, the polynomial positions of the low-order methods, the rest
// test, semi-implicit Euler's parabola). ParticleStepper (particle_stepper.hpp) and the fast
// kernel's lanes build on these.
#pragma once

#include "physics/stepping/contact.hpp"
#include "physics/stepping/events.hpp"
#include "physics/stepping/integrators.hpp"
#include "physics/stepping/kernel.hpp"
#include "physics/stepping/spin_contact.hpp"
#include "physics/stepping/step_trace.hpp"

#include <cmath>
#include <vector>

namespace pl {

struct StepContext {
    const RoomBounds* room;
    const ContactSettings* contact;
    Method method;
    double rtol, atol;
    std::vector<Event>* events;
    AdaptiveStats* adaptive;
    std::uint64_t* contact_solves;
    StepTrace* trace = nullptr;  // metrics' replay of a step only (step_trace.hpp)
};

struct ParticleStep {
    FlightState y;           // position, velocity; ledger deltas per kg for drag and wind
    double radius = 0.0;
    double step_hint = 0.0;  // dopri5
    std::uint8_t resting = 0;
    double bounce_loss = 0.0, friction_loss = 0.0;  // per kg, during this step
    SpinStep spin;  // the generic kernel's, where the model's spin_matters
};

inline bool is_finite(const FlightState& y) {
    return std::isfinite(y.x.x) && std::isfinite(y.x.y) && std::isfinite(y.x.z) && std::isfinite(y.v.x) &&
           std::isfinite(y.v.y) && std::isfinite(y.v.z) && std::isfinite(y.drag_loss) && std::isfinite(y.wind_gain);
}

// Why a stepped particle is frozen instead of stored (none: it is stored).
enum class StepFault : std::uint8_t { none, non_finite, runaway, impact_cap };

// The fault of the state y after a step (`finished`: its impacts all fitted).
inline StepFault step_fault(const FlightState& y, bool finished) {
    if (!is_finite(y)) return StepFault::non_finite;
    if (!finished) return StepFault::impact_cap;
    return glm::dot(y.v, y.v) > runaway_speed_mps * runaway_speed_mps ? StepFault::runaway : StepFault::none;
}

inline WarningKind fault_warning(StepFault f) {
    return f == StepFault::runaway ? WarningKind::runaway
                                   : f == StepFault::impact_cap ? WarningKind::impact_cap : WarningKind::frozen;
}

// Freezes particle i (its last stored state is kept) after the step starting at t0 that ended
// with fault f in state y; the frozen event, and the warning (its value: the speed the step
// reached, for a runaway or the impact cap).
inline Warning freeze_particle(ParticleState& s, std::uint32_t i, double t0, StepFault f, const FlightState& y,
                               std::vector<Event>& events) {
    s.frozen[i] = 1;
    events.push_back({t0, i, -1, EventKind::frozen, glm::length(s.velocity(i)), 0.0});
    return {fault_warning(f), i, t0, f == StepFault::non_finite ? 0.0 : glm::length(y.v)};
}

// Particle i of the state arrays as the stepper's working copy (`hints`: dopri5 only; `radius`:
// the particle's radius).
inline ParticleStep load_step(const ParticleState& s, std::size_t i, const std::vector<double>* hints, double radius) {
    ParticleStep p;
    p.y.x = s.position(i);
    p.y.v = s.velocity(i);
    p.radius = radius;
    p.resting = s.resting[i];
    if (hints) p.step_hint = (*hints)[i];
    return p;
}

// store_step without the bounce and friction ledgers (the fast kernel adds those later). The
// ledger lines no enabled term writes are left untouched.
template <class F>
void store_motion(ParticleState& s, std::size_t i, const ParticleStep& p, std::vector<double>* hints, double mass) {
    s.set_position(i, p.y.x);
    s.set_velocity(i, p.y.v);
    s.resting[i] = p.resting;
    if (hints) (*hints)[i] = p.step_hint;
    if constexpr (F::writes_drag) s.dissipated_drag[i] += mass * p.y.drag_loss;
    if constexpr (F::writes_air_work) s.wind_work[i] += mass * p.y.wind_gain;
}

// Writes a stepped particle back, adding its ledger increments (per-kg losses times `mass`, the
// particle's mass).
template <class F>
void store_step(ParticleState& s, std::size_t i, const ParticleStep& p, std::vector<double>* hints, double mass) {
    store_motion<F>(s, i, p, hints, mass);
    s.dissipated_bounce[i] += mass * p.bounce_loss;
    s.dissipated_friction[i] += mass * p.friction_loss;
}

// store_step with the air column (terms/air_column.hpp): drag and air work per kg of `mass`,
// bounce and friction losses per kg of `inertial`, the inertial mass at the new position.
template <class F>
void store_step(ParticleState& s, std::size_t i, const ParticleStep& p, std::vector<double>* hints, double mass,
                double inertial) {
    store_motion<F>(s, i, p, hints, mass);
    s.inertial_mass[i] = inertial;
    s.dissipated_bounce[i] += inertial * p.bounce_loss;
    s.dissipated_friction[i] += inertial * p.friction_loss;
}

// Adds what one kernel pass counted (force evaluations, adaptive steps, contact solves).
template <class F>
void add_counts(ForceCounters& c, const F& forces, const AdaptiveStats& adaptive, std::uint64_t contact_solves) {
    c += forces.evaluations();
    c.accepted_steps += adaptive.accepted;
    c.rejected_steps += adaptive.rejected;
    c.contacts += contact_solves;
}

// Earliest s in [0, h] at which the wall distance d0 + b s + c s^2 reaches 0, given it is
// below 0 at s = h (h when round-off denies that). Roots by the cancellation-free form
// q = -(b + sgn(b) sqrt(b^2 - 4 c d0)) / 2, s = q / c or d0 / q (Press et al., Numerical Recipes,
// 3rd ed., section 5.6). A sphere already on the wall (d0 <= 0) touches it now unless it moves
// away, and then only where it comes back.
inline double first_contact_root(double d0, double b, double c, double h) {
    // Every case is computed and the one whose conditions hold is selected, without branches:
    // the contact kernel runs this for eight particles at a time (a case that does not apply may
    // compute a NaN or an infinity, which is never selected).
    const bool on_wall = !(d0 > 0.0);
    const bool moving_in = (b < 0.0) | ((b == 0.0) & (c <= 0.0));
    const double back = c < 0.0 ? -b / c : h;     // on the wall moving away: where it returns
    const double linear = b < 0.0 ? -d0 / b : h;  // c == 0
    const double disc = b * b - 4.0 * c * d0;
    const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
    const double r1 = q / c, r2 = d0 / q;
    const double first = r1 > 0.0 ? r1 : INFINITY;
    const double quadratic = disc >= 0.0 ? ((r2 > 0.0) & (r2 < first) ? r2 : first) : h;
    const double s = on_wall ? back : (c == 0.0 ? linear : quadratic);
    // NaN (round-off at a double root) and overshoot: h.
    return on_wall & moving_in ? 0.0 : ((s >= 0.0) & (s <= h) ? s : h);
}

// Whether the method's position after a step of length s is x0 + s v0 + kappa s^2 a0, with a0
// the acceleration at the step start: explicit Euler (kappa = 0) and velocity Verlet (kappa =
// 1/2); semi-implicit Euler's is x0 + s u0 + s^2 a0 / 2 on the parabola of its true velocity
// u0 (file comment), on which its impacts are located (kappa = 1/2 with v0 = u0).
constexpr bool has_polynomial_position(Method m) {
    return m == Method::explicit_euler || m == Method::semi_implicit_euler || m == Method::velocity_verlet;
}
constexpr double position_kappa(Method m) { return m == Method::explicit_euler ? 0.0 : 0.5; }

// Rest instead of a rebound from normal speed `in` to `out` on a wall the net force presses on
// with acceleration `press` (<= 0: not pressed), `remaining` of a step of length h left: below
// the rest threshold, or when the whole series of rebounds e^k out ends within the step (it
// lasts 2 out / (press (1 - e)), Zeno's sum), or the rebound would not rise above the room's
// round-off (out^2 / (2 press) <= room.round_off: where a root search on a step from the wall
// stops), or the impact is no faster than the pressing acceleration gives in `lag` (semi-
// implicit Euler: h, its velocity lags by press h / 2, so a particle lying on the wall meets it
// at that speed on its parabola). Then a particle pressed on the wall with no normal speed
// rests whatever rest_speed is, also with rest_speed = 0 and e = 1.
inline bool settles(double in, double out, double press, const ContactSettings& c, const RoomBounds& room,
                    double remaining, double lag) {
    return (out < c.rest_speed) |
           ((press > 0.0) & ((out <= press * (0.5 * (1.0 - c.restitution) * remaining)) |
                             (out * out <= 2.0 * press * room.round_off) | (in <= press * lag)));
}

// The test of ParticleStepper::lying for one wall: distance d, normal velocity vn and
// acceleration an (positive away from the wall), step h.
inline bool lies_on(double d, double vn, double an, double h) {
    return (d <= 0.0) & (vn <= 0.0) & (an < 0.0) & (-vn <= -an * h);
}

// The flight of a step of length s under the constant forces d (semi-implicit Euler's parabola,
// file comment): exact for a constant acceleration.
inline FlightState parabola(const FlightState& y, double s, const Derivative& d) {
    return {y.x + s * y.v + (0.5 * s * s) * d.a, y.v + s * d.a, y.drag_loss + s * d.drag_power,
            y.wind_gain + s * d.wind_power};
}

// Time of impact on `wall` of a step starting at y whose position is that polynomial.
inline double polynomial_time_of_impact(const RoomBounds& room, int wall, const FlightState& y, double radius,
                                        double kappa, const Vec3& a0, double h) {
    const int axis = RoomBounds::axis(wall);
    const double sign = RoomBounds::is_max(wall) ? -1.0 : 1.0;
    return first_contact_root(room.distance(wall, y.x, radius), sign * y.v[axis], sign * kappa * a0[axis], h);
}

}  // namespace pl
