// Phase 2 of the fast kernel: the flagged particles of a batch that bounce off one wall or slide
// on one wall, stepped in branch-free vector lanes (see fast_kernel.hpp).
// Part of the fast stepping kernel (fast_kernel.hpp), included by fast_kernel.cpp alone, which
// is compiled with -fno-trapping-math (CMakeLists.txt) so that GCC if-converts these selects.
#pragma once

#include "physics/stepping/contact.hpp"
#include "physics/stepping/fast_kernel.hpp"
#include "physics/stepping/flight_chunk.hpp"
#include "physics/stepping/lane_math.hpp"
#include "physics/stepping/particle_state.hpp"
#include "physics/stepping/particle_stepper.hpp"
#include "physics/stepping/slide_lane.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>

namespace pl::fast {

// Flagged particles gathered before phase 2 runs (a full batch fills the vector lanes of the
// contact kernel several times over; it stays small enough for the data to be in cache).
constexpr std::size_t contact_batch = 64;

// Particle i's state into lane j; p is whose mass, radius and drag constants it has.
template <class Lanes>
void gather(Lanes& L, std::size_t j, const ParticleState& s, std::uint32_t i, std::size_t p) {
    L.x[j] = s.x[i];
    L.y[j] = s.y[i];
    L.z[j] = s.z[i];
    L.vx[j] = s.vx[i];
    L.vy[j] = s.vy[i];
    L.vz[j] = s.vz[i];
    L.k[j] = s.drag_k[p];
    L.re_scale[j] = s.drag_re_scale[p];
    L.r[j] = s.radius[p];
    L.m[j] = s.mass[p];
}

// Flagged free particles of one batch, and what bounce_lanes made of them.
struct BounceLanes {
    static constexpr std::size_t capacity = contact_batch + fast_chunk;
    double x[capacity], y[capacity], z[capacity], vx[capacity], vy[capacity], vz[capacity];
    double k[capacity], re_scale[capacity], r[capacity], m[capacity];
    double drag_loss[capacity], wind_gain[capacity], bounce_loss[capacity], friction_loss[capacity];
    double t[capacity], speed_in[capacity], speed_out[capacity];
    std::int64_t wall[capacity], ok[capacity], notify[capacity], flights[capacity];
};

// ParticleStepper::advance for a free particle whose step crosses exactly one wall, that
// rebounds faster than rest_speed and finishes the step without reaching another wall, for
// lanes [0, n) without branches, so that it can vectorise (without wind): every case is
// computed and selected, the wall and its axis are picked by masks instead of indexing.
// ok[j] says the particle took that course; the others are left untouched for the generic
// path. The same operations in the same order as advance; fast_kernel_test checks the bits.
// Flattened and out of line: inlined into the contact phase, GCC left the step calls in it
// as calls, and the loop did not vectorise. It vectorises for every drag model but the
// sphere correlation (which calls pow) without wind (WindField::at is an opaque call).
// forces: the scene's gravity and wind (each lane's drag constants are in the lanes); the rest
// by value, so that the lanes' stores provably cannot alias them.
template <Flight M, class F>
[[gnu::flatten, gnu::noinline]] void bounce_lanes(BounceLanes& L, std::size_t n, const F& forces, const RoomBounds room,
                                                  const ContactSettings contact, const double t0, const double h,
                                                  const double air_density) {
    constexpr double kappa = position_kappa(method_of(M));
    constexpr bool staggered = M == Flight::semi_implicit_euler;
    const double gx = forces.gravity.x, gy = forces.gravity.y, gz = forces.gravity.z;
    const WindField* const wind = forces.wind_field();
    const double lo_x = room.lo.x, lo_y = room.lo.y, lo_z = room.lo.z;
    const double hi_x = room.hi.x, hi_y = room.hi.y, hi_z = room.hi.z;
#pragma GCC ivdep
    for (std::size_t j = 0; j < n; ++j) {
        F f;
        f.load({.gx = gx, .gy = gy, .gz = gz, .wind = wind, .k = L.k[j], .re_scale = L.re_scale[j], .mass = L.m[j],
                .radius = L.r[j], .air_density = air_density});
        const double r = L.r[j];
        FlightState y0;
        y0.x = Vec3(L.x[j], L.y[j], L.z[j]);
        y0.v = Vec3(L.vx[j], L.vy[j], L.vz[j]);
        const FlightState end = fixed_step<M>(y0, t0, h, f);
        const bool c0 = !(end.x.x - (lo_x + r) >= 0.0), c1 = !((hi_x - r) - end.x.x >= 0.0);
        const bool c2 = !(end.x.y - (lo_y + r) >= 0.0), c3 = !((hi_y - r) - end.x.y >= 0.0);
        const bool c4 = !(end.x.z - (lo_z + r) >= 0.0), c5 = !((hi_z - r) - end.x.z >= 0.0);
        const int crossed = c0 + c1 + c2 + c3 + c4 + c5;
        // The highest crossed wall, as the generic stepper picks it (c5 ? 5 : c4 ? 4 : ... : 0),
        // as a maximum: the chain of conditionals was left as branches.
        const std::int64_t wall =
            std::max(std::max(std::max(std::int64_t{c1}, std::int64_t{c2} * 2), std::int64_t{c3} * 3),
                     std::max(std::int64_t{c4} * 4, std::int64_t{c5} * 5));
        const bool is_max = (wall & 1) != 0;
        const Derivative d0 = f(y0.x, y0.v, t0);
        const Vec3 a0 = d0.a;
        // Semi-implicit Euler takes a step that reaches a wall on the parabola of its true
        // velocity u = v + a h / 2 (ParticleStepper, file comment).
        // Selections by wall and axis as bit masks (exact, and they vectorise where a chain
        // of conditionals does not).
        const std::uint64_t w0 = wall == 0 ? ~std::uint64_t{0} : 0, w1 = wall == 1 ? ~std::uint64_t{0} : 0;
        const std::uint64_t w2 = wall == 2 ? ~std::uint64_t{0} : 0, w3 = wall == 3 ? ~std::uint64_t{0} : 0;
        const std::uint64_t w4 = wall == 4 ? ~std::uint64_t{0} : 0, w5 = wall == 5 ? ~std::uint64_t{0} : 0;
        const std::uint64_t ax = w0 | w1, ay = w2 | w3, az = w4 | w5;
        const double d_wall = select6(w0, y0.x.x - (lo_x + r), w1, (hi_x - r) - y0.x.x, w2, y0.x.y - (lo_y + r), w3,
                                      (hi_y - r) - y0.x.y, w4, y0.x.z - (lo_z + r), w5, (hi_z - r) - y0.x.z);
        const double sign = is_max ? -1.0 : 1.0;
        const double a_axis = select3(ax, a0.x, ay, a0.y, az, a0.z);
        // A particle lying on the wall is not turned onto the parabola (ParticleStepper::lying);
        // it rests at once, which the generic path does.
        const bool lies = staggered & lies_on(d_wall, sign * select3(ax, y0.v.x, ay, y0.v.y, az, y0.v.z), sign * a_axis, h);
        const Vec3 u0 = staggered & !lies ? y0.v + (0.5 * h) * a0 : y0.v;
        const double v_axis = select3(ax, u0.x, ay, u0.y, az, u0.z);
        const double s_hit = first_contact_root(d_wall, sign * v_axis, sign * kappa * a_axis, h);
        FlightState start = y0;
        start.v = u0;
        const FlightState part = staggered ? parabola(start, s_hit, d0) : fixed_step<M>(y0, t0, s_hit, f);
        const bool moved = s_hit > 0.0;
        FlightState y;
        y.x = Vec3(when(moved, part.x.x, y0.x.x), when(moved, part.x.y, y0.x.y), when(moved, part.x.z, y0.x.z));
        y.v = Vec3(when(moved, part.v.x, u0.x), when(moved, part.v.y, u0.y), when(moved, part.v.z, u0.z));
        y.drag_loss = when(moved, part.drag_loss, y0.drag_loss);
        y.wind_gain = when(moved, part.wind_gain, y0.wind_gain);
        const double plane =
            select6(w0, lo_x + r, w1, hi_x - r, w2, lo_y + r, w3, hi_y - r, w4, lo_z + r, w5, hi_z - r);
        y.x = Vec3(pick(ax, plane, y.x.x), pick(ay, plane, y.x.y), pick(az, plane, y.x.z));
        y.x = clamp_inside(room, y.x, r);
        const double t = t0 + s_hit, remaining = h - s_hit;
        const double speed_in = glm::length(y.v);
        const double n_sign = is_max ? -1.0 : 1.0;
        const Vec3 normal(pick(ax, n_sign, 0.0), pick(ay, n_sign, 0.0), pick(az, n_sign, 0.0));
        const ImpactResult hit = impact(y.v, normal, contact);
        y.v = hit.v_out;
        const Derivative d1 = f(y.x, y.v, t);  // the forces after the impact: pressed on the wall?
        const bool slow = settles(hit.normal_speed_in, hit.normal_speed_out, -glm::dot(d1.a, normal), contact, room,
                                  remaining, staggered ? h : 0.0);
        const double speed_out = glm::length(y.v);
        const bool go_on = remaining > 0.0;
        FlightState y_end = staggered ? parabola(y, remaining, d1) : fixed_step<M>(y, t, remaining, f);
        const bool end_inside = clear_of_walls(room, y_end.x, r);
        if constexpr (staggered) {
            y_end.v -= (0.5 * h) * d1.a;  // u -> v
            y.v -= (0.5 * h) * d1.a;
        }
        const double ox = when(go_on, y_end.x.x, y.x.x), oy = when(go_on, y_end.x.y, y.x.y);
        const double oz = when(go_on, y_end.x.z, y.x.z), ovx = when(go_on, y_end.v.x, y.v.x);
        const double ovy = when(go_on, y_end.v.y, y.v.y), ovz = when(go_on, y_end.v.z, y.v.z);
        const double loss = when(go_on, y_end.drag_loss, y.drag_loss);
        const double gain = when(go_on, y_end.wind_gain, y.wind_gain);
        // Conservative: a finite state whose sum overflows, or faster than the runaway speed,
        // goes to the generic path too.
        const bool finite = all_finite(ox, oy, oz, loss, gain) & credible(ovx, ovy, ovz);
        L.ok[j] = (crossed == 1) & !slow & !lies & (!go_on | end_inside) & finite;
        L.x[j] = ox;
        L.y[j] = oy;
        L.z[j] = oz;
        L.vx[j] = ovx;
        L.vy[j] = ovy;
        L.vz[j] = ovz;
        L.drag_loss[j] = loss;
        L.wind_gain[j] = gain;
        L.bounce_loss[j] = 0.0 + hit.bounce_loss_per_kg;
        L.friction_loss[j] = 0.0 + hit.friction_loss_per_kg;
        L.t[j] = t;
        L.speed_in[j] = speed_in;
        L.speed_out[j] = speed_out;
        L.wall[j] = wall;
        L.notify[j] = hit.normal_speed_in > 0.0;
        L.flights[j] = staggered ? 1 : 1 + moved + go_on;
    }
}

// Particles resting on one wall, and what slide_lanes made of them.
struct SlideLanes {
    static constexpr std::size_t capacity = contact_batch + fast_chunk;
    double x[capacity], y[capacity], z[capacity], vx[capacity], vy[capacity], vz[capacity];
    double k[capacity], re_scale[capacity], r[capacity], m[capacity];
    double drag_loss[capacity], wind_gain[capacity], friction_loss[capacity];
    std::int64_t wall_bit[capacity], ok[capacity];
};

// slide_lane for lanes [0, n); the arguments as for bounce_lanes.
template <class F>
[[gnu::flatten, gnu::noinline]] void slide_lanes(SlideLanes& L, std::size_t n, const F& forces, const RoomBounds room,
                                                 const double friction, const double t0, const double h,
                                                 const double air_density) {
    const double gx = forces.gravity.x, gy = forces.gravity.y, gz = forces.gravity.z;
    const WindField* const wind = forces.wind_field();
#pragma GCC ivdep
    for (std::size_t j = 0; j < n; ++j) {
        F f;
        f.load({.gx = gx, .gy = gy, .gz = gz, .wind = wind, .k = L.k[j], .re_scale = L.re_scale[j], .mass = L.m[j],
                .radius = L.r[j], .air_density = air_density});
        const Slide q = slide_lane(f, room, friction, t0, h, L.r[j], L.wall_bit[j], L.x[j], L.y[j], L.z[j],
                                   L.vx[j], L.vy[j], L.vz[j]);
        L.ok[j] = q.ok;
        L.x[j] = q.x;
        L.y[j] = q.y;
        L.z[j] = q.z;
        L.vx[j] = q.vx;
        L.vy[j] = q.vy;
        L.vz[j] = q.vz;
        L.drag_loss[j] = q.drag_loss;
        L.wind_gain[j] = q.wind_gain;
        L.friction_loss[j] = q.friction_loss;
    }
}

}  // namespace pl::fast
