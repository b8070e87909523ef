// Advances one particle through one fixed step, with exact wall handling:
//  * in flight the chosen method integrates; if the end of the step is outside a wall, the
//    time of impact is located on the step's own trajectory: in closed form where the
//    position is a quadratic in the step length (explicit and semi-implicit Euler, velocity
//    Verlet), otherwise by a bracketing root search on the method re-run with a shorter step
//    (for adaptive Dormand-Prince, on its dense output inside the internal step that
//    crossed, or that passed the wall and came back within it); the particle is advanced to
//    the wall, the impact response is applied, and the rest of the step continues from there;
//  * semi-implicit Euler's velocity at the end of a step is the velocity of the middle of it:
//    under a constant acceleration a its positions lie on the exact parabola of the velocity
//    u = v + a h / 2 (Hairer, Lubich & Wanner, Geometric Numerical Integration, I.1: the
//    method conserves the modified energy u^2/2 - a.x). A step that reaches a wall is therefore
//    taken on that parabola: v is turned into u, the impact is located on the parabola and
//    applied to the true impact velocity, the rest of the step follows the parabola, and the
//    end velocity is turned back (v = u - a h / 2). Split there into substeps of the method
//    itself, every bounce arc lost speed (an elastic ball came to rest);
//  * a particle resting on walls (rebound speed fell below rest_speed while the net force
//    pressed it on the wall, or a rebound too slow to leave the wall within the step) moves in
//    the wall's plane with the normal force cancelling the pressing acceleration and Coulomb
//    friction mu N opposing sliding; static friction holds it when the tangential force is
//    below mu N. Its normal velocity is exactly 0 and its position exactly on the plane, so it
//    cannot jitter or sink;
//  * walls reached at the same instant (a corner) take their impacts together (corner_impact),
//    so the result does not depend on the order of the walls;
//  * a step needing more than max_impacts_per_step impacts is not finished: advance says so and
//    the kernel freezes the particle and reports it, as it does a non-finite or runaway state.
#pragma once

#include "physics/model/restitution.hpp"
#include "physics/stepping/contact.hpp"
#include "physics/stepping/events.hpp"
#include "physics/stepping/integrators.hpp"
#include "physics/stepping/kernel.hpp"
#include "physics/stepping/particle_step.hpp"
#include "physics/stepping/spin_contact.hpp"

#include <bit>
#include <cmath>
#include <vector>

namespace pl {

template <class F>
class ParticleStepper {
public:
    ParticleStepper(const StepContext& ctx, const F& f) : c_(ctx), f_(f) {}

    // Returns false when the step needed more than max_impacts_per_step impacts (p is then the
    // state at the last of them; the caller freezes the particle).
    bool advance(ParticleStep& p, std::uint32_t id, double t0, double h) const {
        double t = t0, remaining = h;
        // Semi-implicit Euler once a wall is reached: p.y.v holds the true velocity u, `seg` the
        // forces at the start of the parabola it follows (see the file comment).
        bool on_parabola = false, seg_fresh = false;
        Derivative seg{};
        for (int guard = 0; remaining > 0.0; ++guard) {
            if (guard > max_impacts_per_step) return false;
            if (p.resting) {
                // The forces at the step start decide the release and drive the slide (the
                // release changes only which walls hold the particle, not x or v).
                const Derivative d = f_(p.y.x, p.y.v, t);
                if (release_walls(p, id, t, d)) continue;
                slide(p, id, t, remaining, h, d);
                return true;
            }
            int wall = -1;
            std::uint8_t walls = 0;  // the walls reached at s_hit
            double s_hit = remaining;
            if (adaptive()) {
                if (!adaptive_flight(p, t, remaining, wall, s_hit)) return true;
                walls = static_cast<std::uint8_t>(1u << wall);
            } else {
                if (on_parabola && !seg_fresh) seg = f_(p.y.x, p.y.v, t);
                const FlightState end = on_parabola ? parabola(p.y, remaining, seg) : flight(p, t, remaining);
                Derivative d0{};
                for (int w = 0; w < wall_count; ++w) {
                    if (c_.room->distance(w, end.x, p.radius) >= 0.0) continue;
                    if (wall < 0 && polynomial_position()) {
                        d0 = on_parabola ? seg : f_(p.y.x, p.y.v, t);
                        if (staggered() && !on_parabola && !lying(p, d0.a, remaining)) {
                            p.y.v = p.y.v + (0.5 * remaining) * d0.a;  // v -> u (file comment)
                            on_parabola = true;
                            seg = d0;
                        }
                    }
                    const double s = time_of_impact(p, w, t, remaining, d0.a);
                    if (wall < 0 || s < s_hit) {
                        wall = w;
                        s_hit = s;
                        walls = 0;
                    }
                    if (s == s_hit) walls |= static_cast<std::uint8_t>(1u << w);
                }
                if (wall < 0) {
                    if (c_.trace) [[unlikely]] trace_flight(p, t, remaining, on_parabola, seg);
                    p.y = end;
                    if (on_parabola) p.y.v -= (0.5 * h) * seg.a;  // u -> v
                    return true;
                }
                if (c_.trace) [[unlikely]] trace_flight(p, t, s_hit, on_parabola, seg);
                if (s_hit > 0.0) p.y = on_parabola ? parabola(p.y, s_hit, seg) : flight(p, t, s_hit);
            }
            ++*c_.contact_solves;
            for (int w = 0; w < wall_count; ++w)
                if (walls & (1u << w)) p.y.x[RoomBounds::axis(w)] = c_.room->contact_plane(w, p.radius);
            p.y.x = c_.room->clamp_inside(p.y.x, p.radius);
            if (c_.trace) [[unlikely]] c_.trace->impact(t + s_hit, p.y.x);
            t += s_hit;
            remaining -= s_hit;
            seg_fresh = hit_walls(p, id, walls, t, remaining, h, seg);
            if (p.resting) on_parabola = false;  // resting contact has its own velocity (slide)
        }
        if (on_parabola) p.y.v -= (0.5 * h) * seg.a;
        return true;
    }

private:
    FlightState flight(ParticleStep& p, double t, double h) const {
        switch (c_.method) {
            case Method::explicit_euler: return explicit_euler_step(p.y, t, h, f_);
            case Method::semi_implicit_euler: return semi_implicit_euler_step(p.y, t, h, f_);
            case Method::velocity_verlet: return velocity_verlet_step(p.y, t, h, f_);
            case Method::rk4: return rk4_step(p.y, t, h, f_);
            case Method::exponential: return exponential_step(p.y, t, h, f_);
            case Method::dopri5: return dopri5_step(p.y, t, h, f_, c_.rtol, c_.atol).y1;  // fixed step
        }
        return p.y;
    }

    bool adaptive() const { return c_.method == Method::dopri5 && c_.adaptive != nullptr; }

    // Adaptive Dormand-Prince over [t, t + h], as many internal steps as the tolerance needs.
    // After each accepted internal step the walls are checked; an impact inside it is located
    // on the method's dense output, and p.y is set to the state there. Returns whether a wall
    // was hit (then `wall` and `s_hit`, the time from t, are set); otherwise p.y is the state
    // at t + h. p.step_hint carries the last good internal step between calls.
    bool adaptive_flight(ParticleStep& p, double t, double h, int& wall, double& s_hit) const {
        double done = 0.0;
        double step = (p.step_hint > 0.0 && p.step_hint < h) ? p.step_hint : h;
        for (int guard = 0; done < h && guard < 100000; ++guard) {
            const bool last = step >= h - done;
            const double s = last ? h - done : step;
            const DopriStep trial = dopri5_step(p.y, t + done, s, f_, c_.rtol, c_.atol);
            if (trial.err_norm > 1.0 && s > 1e-12 * h) {
                ++c_.adaptive->rejected;
                step = s * dopri5_step_factor(trial.err_norm);
                continue;
            }
            ++c_.adaptive->accepted;
            const double grown = s * dopri5_step_factor(trial.err_norm);
            p.step_hint = last ? std::max(step, grown) : grown;
            wall = -1;
            double theta_hit = 1.0;
            auto take_earliest = [&](int w, double theta) {
                if (wall < 0 || theta < theta_hit) { wall = w; theta_hit = theta; }
            };
            for (int w = 0; w < wall_count; ++w) {
                if (c_.room->distance(w, trial.y1.x, p.radius) >= 0.0) continue;
                take_earliest(w, find_contact(
                                     [&](double th) { return c_.room->distance(w, trial.at(th).x, p.radius); }, 1.0));
            }
            // A wall passed and left within the step: only along an axis whose velocity changed
            // sign, towards the wall it was moving to (one product per axis in the common case).
            for (int axis = 0; axis < 3; ++axis) {
                const double v0 = p.y.v[axis];
                if (!(v0 * trial.y1.v[axis] < 0.0)) continue;
                const int w = 2 * axis + (v0 > 0.0 ? 1 : 0);  // Wall: x_min, x_max, y_min, ...
                auto distance = [&](double th) { return c_.room->distance(w, trial.at(th).x, p.radius); };
                const double closest = turning_point(p.y, trial, w, p.radius, s);
                if (closest > 0.0 && distance(closest) < 0.0) take_earliest(w, find_contact(distance, closest));
            }
            if (c_.trace) [[unlikely]]
                c_.trace->flight(t + done, theta_hit * s, [&](double q) { return trial.at(q / s); });
            if (wall >= 0) {
                p.y = trial.at(theta_hit);
                s_hit = std::min(h, done + theta_hit * s);
                return true;
            }
            p.y = trial.y1;
            done = last ? h : done + s;
            step = p.step_hint;
        }
        return false;
    }

    // A long internal step can end clear of a wall it passed through on the way: a ball whose
    // apex lies beyond the ceiling, a glancing pass along a side wall. For a step whose velocity
    // along the wall's normal turns from towards it to away from it (the caller checks the turn),
    // the closest approach is found on the dense output by golden-section search (the distance
    // is unimodal around a single turn) and returned as a fraction of the step; -1 where the wall
    // is further than the step could have carried the particle towards it (the speed towards it
    // falls until the turn, so the approach is at most |v_n| s).
    double turning_point(const FlightState& y0, const DopriStep& trial, int w, double radius, double s) const {
        const double speed_towards = -glm::dot(y0.v, RoomBounds::inward_normal(w));
        if (c_.room->distance(w, y0.x, radius) > speed_towards * s) return -1.0;
        auto distance = [&](double th) { return c_.room->distance(w, trial.at(th).x, radius); };
        constexpr double golden = 0.6180339887498949;
        double lo = 0.0, hi = 1.0;
        double a = hi - golden * (hi - lo), b = lo + golden * (hi - lo);
        double d_a = distance(a), d_b = distance(b);
        for (int it = 0; it < 64 && hi - lo > 1e-12; ++it) {
            if (d_a < d_b) {
                hi = b;
                b = a;
                d_b = d_a;
                a = hi - golden * (hi - lo);
                d_a = distance(a);
            } else {
                lo = a;
                a = b;
                d_a = d_b;
                b = lo + golden * (hi - lo);
                d_b = distance(b);
            }
        }
        return d_a < d_b ? a : b;
    }

    bool polynomial_position() const { return has_polynomial_position(c_.method); }

    // A traced step (StepContext::trace): the flight from p.y at t over s on the step's own
    // trajectory (step_trace.hpp), where the stepper is about to take it.
    void trace_flight(const ParticleStep& p, double t, double s, bool on_parabola, const Derivative& seg) const {
        if (polynomial_position()) {
            const Vec3 a0 = on_parabola ? seg.a : f_(p.y.x, p.y.v, t).a;
            // Semi-implicit Euler off its parabola (a step that reaches no wall): the parabola
            // through the step's end point, of the velocity u0 = v0 + a0 s / 2.
            const double u0 = staggered() && !on_parabola ? p.y.v.y + 0.5 * s * a0.y : p.y.v.y;
            c_.trace->quadratic_flight(t, s, p.y.x.y, u0, position_kappa(c_.method) * a0.y);
        } else {
            ParticleStep start = p;
            c_.trace->flight(t, s, [&](double q) { return flight(start, t, q); });
        }
    }

    // Whether the particle lies on a wall that presses it, with a normal velocity into it no
    // larger than the pressing acceleration gives in h: semi-implicit Euler's state of a particle
    // at rest on a wall (its velocity lags by a h / 2), which takes no impact on its parabola
    // (that impact's friction would brake a slide that has not started) but rests at once.
    bool lying(const ParticleStep& p, const Vec3& a, double h) const {
        for (int w = 0; w < wall_count; ++w) {
            const Vec3 n = RoomBounds::inward_normal(w);
            if (lies_on(c_.room->distance(w, p.y.x, p.radius), glm::dot(p.y.v, n), glm::dot(a, n), h)) return true;
        }
        return false;
    }
    bool staggered() const { return c_.method == Method::semi_implicit_euler; }

    // Earliest s in [0, h] at which the sphere touches `wall`, given it is beyond it at s = h,
    // on the fixed-step method's own trajectory (the step re-run with length s): in closed form
    // where that trajectory is a polynomial in s (a0 = acceleration at the step start), by a
    // root search otherwise.
    double time_of_impact(ParticleStep& p, int wall, double t, double h, const Vec3& a0) const {
        if (polynomial_position())
            return polynomial_time_of_impact(*c_.room, wall, p.y, p.radius, position_kappa(c_.method), a0, h);
        return find_contact([&](double s) { return c_.room->distance(wall, flight(p, t, s).x, p.radius); }, h);
    }

    // The impact on `walls` (a bit mask: several where they are reached at the same instant) at
    // time t, with `remaining` of the step (of length h) left. Sets `d` to the forces just after
    // it and returns whether they still hold for the particle's state (no normal velocity was
    // zeroed after them).
    bool hit_walls(ParticleStep& p, std::uint32_t id, std::uint8_t walls, double t, double remaining, double h,
                   Derivative& d) const {
        const Vec3 v_in = p.y.v;
        const double speed_in = glm::length(v_in);
        const bool single = std::has_single_bit(walls);
        // One wall: the restitution law at this impact speed, and the spin coupling when the scene
        // has it; a corner (walls at the same instant) takes the point-mass impact on each.
        const Vec3 n_single = RoomBounds::inward_normal(std::countr_zero(walls));
        const ContactSettings contact = single ? at_impact_speed(*c_.contact, -glm::dot(v_in, n_single)) : *c_.contact;
        const ImpactResult r = !single        ? corner_impact(v_in, walls, contact)
                               : contact.spin ? spin_impact(v_in, p.spin, n_single, p.radius, contact, t)
                                              : impact(v_in, n_single, contact);
        p.bounce_loss += r.bounce_loss_per_kg;
        p.friction_loss += r.friction_loss_per_kg;
        p.y.v = r.v_out;
        d = f_(p.y.x, p.y.v, t);
        bool fresh = true;
        for (int wall = 0; wall < wall_count; ++wall) {
            if (!(walls & (1u << wall))) continue;
            const Vec3 n = RoomBounds::inward_normal(wall);
            const double normal_in = single ? r.normal_speed_in : std::max(0.0, -glm::dot(v_in, n));
            const double normal_out = single ? r.normal_speed_out : contact.restitution * normal_in;
            EventKind kind = EventKind::bounce;
            const double press = -glm::dot(d.a, n);
            if (settles(normal_in, normal_out, press, contact, *c_.room, remaining, staggered() ? h : 0.0)) {
                // Below the rest threshold (or too slow to leave the wall within the step) the
                // remaining micro-bounces (which would sum to a finite time, t0 (1+e)/(1-e) for a
                // drop) are replaced by resting contact when the net force presses the particle
                // on the wall. Against a wall nothing presses it on, a lossy wall (e < 1) still
                // ends the slow normal motion, so it cannot creep forever.
                const bool pressed = press > 0.0;
                if (pressed || contact.restitution < 1.0) {
                    p.bounce_loss += 0.5 * normal_out * normal_out;
                    p.y.v -= glm::dot(p.y.v, n) * n;
                    fresh = false;
                }
                if (pressed) {
                    p.resting |= static_cast<std::uint8_t>(1u << wall);
                    kind = EventKind::rest;
                }
            }
            if (normal_in > 0.0 || kind == EventKind::rest)
                c_.events->push_back({t, id, static_cast<std::int8_t>(wall), kind, speed_in, glm::length(p.y.v)});
        }
        return fresh;
    }

    // Leaves every resting wall that the particle is kicked or pulled away from; returns true
    // when it is no longer resting on any wall.
    bool release_walls(ParticleStep& p, std::uint32_t id, double t, const Derivative& d) const {
        for (int w = 0; w < wall_count; ++w) {
            if (!(p.resting & (1u << w))) continue;
            const Vec3 n = RoomBounds::inward_normal(w);
            if (glm::dot(d.a, n) > 0.0 || glm::dot(p.y.v, n) > 0.0) {
                p.resting &= static_cast<std::uint8_t>(~(1u << w));
                const double s = glm::length(p.y.v);
                c_.events->push_back({t, id, static_cast<std::int8_t>(w), EventKind::lift, s, s});
            }
        }
        return p.resting == 0;
    }

    // Resting contact for the remaining h of the step of length `step` (see file comment).
    void slide(ParticleStep& p, std::uint32_t id, double t, double h, double step, const Derivative& d) const {
        if (c_.contact->spin && spin_slide(p, *c_.room, *c_.contact, t, h, d, c_.events, id, [&](int w, double t_hit) {
                Derivative after;
                hit_walls(p, id, static_cast<std::uint8_t>(1u << w), t_hit, t + h - t_hit, step, after);
            }))
            return;
        Vec3 a = d.a;
        double press = 0.0;
        for (int w = 0; w < wall_count; ++w) {
            if (!(p.resting & (1u << w))) continue;
            const Vec3 n = RoomBounds::inward_normal(w);
            const double an = glm::dot(a, n);
            press -= an;  // an <= 0 here: release_walls took the others
            a -= an * n;
            p.y.v -= glm::dot(p.y.v, n) * n;
        }
        const Vec3 v_free = p.y.v + h * a;
        const double jump = h * c_.contact->friction * press;  // Coulomb: |dv| <= mu N h / m
        const double speed = glm::length(v_free);
        const bool was_moving = p.y.v != Vec3(0.0);
        const Vec3 v_new = speed <= jump ? Vec3(0.0) : v_free * (1.0 - jump / speed);
        p.friction_loss += 0.5 * (speed * speed - glm::dot(v_new, v_new));
        p.y.drag_loss += h * d.drag_power;
        p.y.wind_gain += h * d.wind_power;
        if (!was_moving && v_new == Vec3(0.0)) {  // held by static friction
            p.y.v = v_new;
            return;
        }
        // The mean velocity of the step moves the particle: the trapezoid (v + v_new) / 2, exact
        // for constant forces; a particle that stops does so at the time of stop inside the step,
        // tau = |v| / D with D its deceleration, having moved v tau / 2 (exact for constant
        // friction, the slide's closed form v^2 / (2 mu g)). At the step end, as a first-order
        // step, it had moved h v_new, stopped not at all: a stop distance off by v dt / 2.
        double t_stop = h;
        if (v_new == Vec3(0.0)) {
            const double v_len = glm::length(p.y.v);
            const double decel = c_.contact->friction * press - glm::dot(a, p.y.v) / v_len;
            t_stop = decel > 0.0 ? std::min(h, v_len / decel) : h;
            p.y.v = p.y.v * (0.5 * t_stop / h);
            c_.events->push_back({t + t_stop, id, -1, EventKind::stop, v_len, 0.0});
        } else {
            p.y.v = 0.5 * (p.y.v + v_new);
        }
        if (!slide_along(p, id, t, h, step)) p.y.v = v_new;
    }

    // Straight-line motion at p.y.v for h along the walls (slide): walls it slides into are found
    // exactly, and take an impact (p.y.v is then what the impacts left). Returns whether it hit one.
    bool slide_along(ParticleStep& p, std::uint32_t id, double t, double h, double step) const {
        double remaining = h;
        bool hit = false;
        for (int guard = 0; guard < 16 && remaining > 0.0; ++guard) {
            const Vec3 end = p.y.x + remaining * p.y.v;
            int wall = -1;
            double s_hit = remaining;
            for (int w = 0; w < wall_count; ++w) {
                const double d_end = c_.room->distance(w, end, p.radius);
                if (d_end >= 0.0) continue;
                const double d0 = std::max(0.0, c_.room->distance(w, p.y.x, p.radius));
                const double s = remaining * d0 / (d0 - d_end);
                if (wall < 0 || s < s_hit) { wall = w; s_hit = s; }
            }
            if (wall < 0) {
                p.y.x = end;
                break;
            }
            p.y.x += s_hit * p.y.v;
            p.y.x[RoomBounds::axis(wall)] = c_.room->contact_plane(wall, p.radius);
            remaining -= s_hit;
            Derivative after;
            hit_walls(p, id, static_cast<std::uint8_t>(1u << wall), t + h - remaining, remaining, step, after);
            hit = true;
            if (p.y.v == Vec3(0.0)) {
                c_.events->push_back({t + h - remaining, id, -1, EventKind::stop, 0.0, 0.0});
                break;
            }
        }
        p.y.x = c_.room->clamp_inside(p.y.x, p.radius);
        return hit;
    }

    const StepContext& c_;
    const F& f_;
};

}  // namespace pl
