// Phase 1 of the fast kernel: the vectorised flight of a chunk of particles (see fast_kernel.hpp).
// Part of the fast stepping kernel (fast_kernel.hpp), included by fast_kernel.cpp alone, which
// is compiled with -fno-trapping-math (CMakeLists.txt) so that GCC if-converts these selects.
#pragma once

#include "physics/stepping/contact.hpp"
#include "physics/stepping/fast_kernel.hpp"
#include "physics/model/forces.hpp"
#include "physics/model/terms/wind.hpp"
#include "physics/stepping/held_lanes.hpp"
#include "physics/stepping/integrators.hpp"
#include "physics/stepping/lane_math.hpp"
#include "physics/stepping/particle_state.hpp"

#include <bit>
#include <cfloat>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <type_traits>

namespace pl::fast {

// The fixed-step methods phase 1 runs; `none` sends every particle to phase 2.
enum class Flight { none, explicit_euler, semi_implicit_euler, velocity_verlet, rk4 };

constexpr Method method_of(Flight m) {
    switch (m) {
        case Flight::explicit_euler: return Method::explicit_euler;
        case Flight::semi_implicit_euler: return Method::semi_implicit_euler;
        case Flight::velocity_verlet: return Method::velocity_verlet;
        case Flight::rk4: return Method::rk4;
        case Flight::none: break;
    }
    return Method::dopri5;  // stands for "no fixed-step flight phase"
}

template <Flight M, class F>
FlightState fixed_step(const FlightState& y, double t, double h, const F& f) {
    if constexpr (M == Flight::explicit_euler) return explicit_euler_step(y, t, h, f);
    else if constexpr (M == Flight::semi_implicit_euler) return semi_implicit_euler_step(y, t, h, f);
    else if constexpr (M == Flight::velocity_verlet) return velocity_verlet_step(y, t, h, f);
    else return rk4_step(y, t, h, f);
}

// Methods whose one force evaluation per step is at the step start: for them phase 1 looks the
// wind up for the whole chunk first (WindField::at is an opaque call), then runs the vector loop.
template <Flight M, bool HasWind>
constexpr bool wind_ahead = HasWind && (M == Flight::explicit_euler || M == Flight::semi_implicit_euler);

namespace detail {
template <class F>
struct with_known_wind;
template <class... Terms>
struct with_known_wind<Forces<Terms...>> {
    using type = Forces<std::conditional_t<std::is_same_v<Terms, terms::Wind>, terms::KnownWind, Terms>...>;
};
}  // namespace detail

// The force functor phase 1 uses for one particle, filled in place from scalars (Forces::load):
// GCC keeps it in registers only if no glm vector or whole functor is copied (the copy of a
// union-based glm::dvec3 blocks scalarisation, and with it vectorisation). Where the wind is
// looked up ahead, the wind term is the one that holds the known w (terms/wind.hpp).
template <Flight M, class F>
using FlightForces = std::conditional_t<wind_ahead<M, F::has_wind>, typename detail::with_known_wind<F>::type, F>;

// Phase 1 for particles [begin, end), at most fast_chunk of them: see fast_kernel.hpp. Sets bit
// j of flagged[k] for particle begin + 64 k + j where it leaves the particle for phase 2 (and
// clears the others); returns the number of particles it finished. The held particles (resting
// or frozen, left alone) come as the same bits in held_bits. Identical: every particle has the
// mass, radius and drag constants of particle 0, so they are read once instead of streamed.
// WholeVectors: the state is written back in whole vectors (old values where a particle is
// left for phase 2) instead of masked stores. Measured on the development machine (AVX-512,
// bench/RESULTS.md): masked stores are faster while the state is in cache, whole vectors when it
// streams from memory (about +10% at 1e6 particles, -13% at 1e4). Out of line: inlined into the
// range loop, its speed moved by up to 20% with unrelated changes to the code around it.
template <Flight M, class F, bool Identical, bool WholeVectors>
[[gnu::flatten, gnu::noinline]] std::size_t flight_chunk(ParticleState& s, std::size_t begin, std::size_t end,
                                                         const F& forces, const RoomBounds& room, double t0, double h,
                                                         double air_density, const LaneBits* held_bits,
                                                         LaneBits* flagged) {
    // Local copies the stores below provably cannot alias.
    const double gx = forces.gravity.x, gy = forces.gravity.y, gz = forces.gravity.z;
    const double lo_x = room.lo.x, lo_y = room.lo.y, lo_z = room.lo.z;
    const double hi_x = room.hi.x, hi_y = room.hi.y, hi_z = room.hi.z;
    const WindField* const wind = forces.wind_field();
    double* const px = s.x.data();
    double* const py = s.y.data();
    double* const pz = s.z.data();
    double* const vx = s.vx.data();
    double* const vy = s.vy.data();
    double* const vz = s.vz.data();
    double* const drag_loss = s.dissipated_drag.data();
    double* const wind_work = s.wind_work.data();
    const double* const mass = s.mass.data();
    const double* const radius = s.radius.data();
    const double* const drag_k = s.drag_k.data();
    const double* const re_scale = s.drag_re_scale.data();
    const double mass0 = mass[0], radius0 = radius[0], k0 = drag_k[0], re_scale0 = re_scale[0];
    double wx[fast_chunk], wy[fast_chunk], wz[fast_chunk];
    if constexpr (wind_ahead<M, F::has_wind>) {
        for (std::size_t i = begin; i < end; ++i) {
            const Vec3 w = wind->at(Vec3(px[i], py[i], pz[i]), t0);
            wx[i - begin] = w.x;
            wy[i - begin] = w.y;
            wz[i - begin] = w.z;
        }
    }
    // One particle's flight; returns whether its new state was kept.
    const auto fly = [&](std::size_t i, bool free_lane) [[gnu::always_inline]] {
        double w[3] = {0.0, 0.0, 0.0};
        if constexpr (wind_ahead<M, F::has_wind>) {
            w[0] = wx[i - begin];
            w[1] = wy[i - begin];
            w[2] = wz[i - begin];
        }
        const double m = Identical ? mass0 : mass[i];
        const double r = Identical ? radius0 : radius[i];
        FlightForces<M, F> f;
        f.load({.gx = gx, .gy = gy, .gz = gz, .wind = wind, .k = Identical ? k0 : drag_k[i],
                .re_scale = Identical ? re_scale0 : re_scale[i], .wx = w[0], .wy = w[1], .wz = w[2], .mass = m,
                .radius = r, .air_density = air_density});
        FlightState y0;
        y0.x = Vec3(px[i], py[i], pz[i]);
        y0.v = Vec3(vx[i], vy[i], vz[i]);
        const FlightState y1 = fixed_step<M>(y0, t0, h, f);
        // The generic stepper's "no wall reached" test, RoomBounds::distance(w, x, r) >= 0 for
        // every wall, as x >= lo + r and x <= hi - r: the sign of a difference is exact, so the
        // same decision. It also implies a finite position, so only the rest is checked below.
        const bool inside = (y1.x.x >= lo_x + r) & (y1.x.x <= hi_x - r) & (y1.x.y >= lo_y + r) &
                            (y1.x.y <= hi_y - r) & (y1.x.z >= lo_z + r) & (y1.x.z <= hi_z - r);
        // A velocity beyond the runaway speed (Inf and NaN too) goes to the generic path, which
        // freezes the particle.
        const bool finite = (std::abs(y1.drag_loss) + std::abs(y1.wind_gain) <= DBL_MAX) & credible(y1.v.x, y1.v.y, y1.v.z);
        const bool take = inside & finite & free_lane;
        if constexpr (WholeVectors) {
            const std::uint64_t keep_new = take ? ~std::uint64_t{0} : 0;
            px[i] = pick(keep_new, y1.x.x, y0.x.x);
            py[i] = pick(keep_new, y1.x.y, y0.x.y);
            pz[i] = pick(keep_new, y1.x.z, y0.x.z);
            vx[i] = pick(keep_new, y1.v.x, y0.v.x);
            vy[i] = pick(keep_new, y1.v.y, y0.v.y);
            vz[i] = pick(keep_new, y1.v.z, y0.v.z);
        } else {
            px[i] = take ? y1.x.x : px[i];
            py[i] = take ? y1.x.y : py[i];
            pz[i] = take ? y1.x.z : pz[i];
            vx[i] = take ? y1.v.x : vx[i];
            vy[i] = take ? y1.v.y : vy[i];
            vz[i] = take ? y1.v.z : vz[i];
        }
        // The generic kernel also adds mass * 0 to the bounce and friction ledgers, which
        // leaves them unchanged (they start at +0 and never become -0): skipped here.
        if constexpr (F::writes_drag) drag_loss[i] = take ? drag_loss[i] + m * y1.drag_loss : drag_loss[i];
        if constexpr (F::writes_air_work) wind_work[i] = take ? wind_work[i] + m * y1.wind_gain : wind_work[i];
        return take;
    };
    // The flags of a group of 64 are ORed into its word in the loop. How the loop reads a
    // particle's bit sets how many particles GCC takes per iteration: a shift (whose count is a
    // 32-bit int) makes it 16, a load from bit_of 8. From memory 16 are faster (engine/limit +6-7%
    // at 1e6 particles, one step per call, over 64-bit lanes in and out), in cache 8 (16 were
    // 12-23% slower; 8 equal to 64-bit lanes). Alternating runs of two builds, bench/RESULTS.md.
    std::size_t flagged_count = 0;
    for (std::size_t g = begin; g < end; g += lane_group) {
        const std::size_t len = end - g < lane_group ? end - g : lane_group;
        const LaneBits held = held_bits[(g - begin) / lane_group];
        LaneBits flags = 0;
#pragma GCC ivdep
        for (std::size_t j = 0; j < len; ++j) {
            if constexpr (WholeVectors) {
                // Bit j of `held` moved to the sign bit (GCC vectorises this, not a shift right).
                const bool free_lane = static_cast<std::int64_t>(held << (lane_group - 1 - j)) >= 0;
                flags |= LaneBits{!fly(g + j, free_lane)} << j;
            } else {
                flags |= bit_if(!fly(g + j, (held & bit_of[j]) == 0), j);
            }
        }
        flagged[(g - begin) / lane_group] = flags;
        flagged_count += static_cast<std::size_t>(std::popcount(flags));
    }
    return (end - begin) - flagged_count;
}

}  // namespace pl::fast
