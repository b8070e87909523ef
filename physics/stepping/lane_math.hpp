// Branch-free per-lane arithmetic of the fast kernel's vector loops: selects as bit masks,
// finiteness as a compare, the room's walls written out so that GCC vectorises them.
// Part of the fast stepping kernel (fast_kernel.hpp), included by fast_kernel.cpp alone, which
// is compiled with -fno-trapping-math (CMakeLists.txt) so that GCC if-converts these selects.
#pragma once

#include "physics/stepping/contact.hpp"
#include "physics/stepping/warnings.hpp"

#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdint>

namespace pl::fast {

// False if any of them is Inf or NaN, as a plain compare that vectorises (std::isfinite does
// not). Finite values whose sum overflows also give false: the particle then merely takes the
// generic path, which decides exactly as it always does.
inline bool all_finite(double a, double b, double c, double d, double e) {
    return std::abs(a) + std::abs(b) + std::abs(c) + std::abs(d) + std::abs(e) <= DBL_MAX;
}

// Whether a velocity is below the runaway speed (step_fault), as a plain compare that
// vectorises: |vx| + |vy| + |vz| >= |v|, so true implies the generic test passes (a false
// merely sends the particle to the generic path). False for Inf and NaN too.
inline bool credible(double vx, double vy, double vz) {
    return std::abs(vx) + std::abs(vy) + std::abs(vz) <= runaway_speed_mps;
}

// a where mask is all ones, b where it is zero, as bit operations: GCC turns a select whose
// other side is the value already in memory into a masked store, and this it cannot.
inline double pick(std::uint64_t mask, double a, double b) {
    return std::bit_cast<double>((std::bit_cast<std::uint64_t>(a) & mask) | (std::bit_cast<std::uint64_t>(b) & ~mask));
}

// c ? a : b for lanes; GCC if-converts this where it leaves some ternaries as branches.
inline double when(bool c, double a, double b) { return pick(std::uint64_t{0} - c, a, b); }

// RoomBounds::clamp_inside, written out so that it vectorises: glm::clamp per axis is
// min(max(x, l), h) with glm's max(x, l) = x < l ? l : x and min(m, h) = h < m ? h : m.
inline double clamp_axis(double x, double lo, double hi, double r) {
    const double l = lo + r, h = hi - r;
    const double up = when(x < l, l, x);
    return when(l <= h, when(h < up, h, up), 0.5 * (lo + hi));
}
inline Vec3 clamp_inside(const RoomBounds& room, const Vec3& x, double r) {
    return Vec3(clamp_axis(x.x, room.lo.x, room.hi.x, r), clamp_axis(x.y, room.lo.y, room.hi.y, r),
                clamp_axis(x.z, room.lo.z, room.hi.z, r));
}

// RoomBounds::distance(w, x, r) >= 0 for every wall w, written out so that it vectorises.
inline bool clear_of_walls(const RoomBounds& room, const Vec3& x, double r) {
    return (x.x - (room.lo.x + r) >= 0.0) & ((room.hi.x - r) - x.x >= 0.0) & (x.y - (room.lo.y + r) >= 0.0) &
           ((room.hi.y - r) - x.y >= 0.0) & (x.z - (room.lo.z + r) >= 0.0) & ((room.hi.z - r) - x.z >= 0.0);
}

// The one of a, b, c (d, e, f) whose mask is all ones; exactly one mask is.
inline double select3(std::uint64_t ma, double a, std::uint64_t mb, double b, std::uint64_t mc, double c) {
    return std::bit_cast<double>((std::bit_cast<std::uint64_t>(a) & ma) | (std::bit_cast<std::uint64_t>(b) & mb) |
                                 (std::bit_cast<std::uint64_t>(c) & mc));
}
inline double select6(std::uint64_t ma, double a, std::uint64_t mb, double b, std::uint64_t mc, double c,
                      std::uint64_t md, double d, std::uint64_t me, double e, std::uint64_t mf, double f) {
    return std::bit_cast<double>(std::bit_cast<std::uint64_t>(select3(ma, a, mb, b, mc, c)) |
                                 std::bit_cast<std::uint64_t>(select3(md, d, me, e, mf, f)));
}

}  // namespace pl::fast
