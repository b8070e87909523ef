// The slide of one particle resting on one wall, branch-free, for the fast kernel's vector loops.
// Part of the fast stepping kernel (fast_kernel.hpp), included by fast_kernel.cpp alone, which
// is compiled with -fno-trapping-math (CMakeLists.txt) so that GCC if-converts these selects.
#pragma once

#include "physics/stepping/contact.hpp"
#include "physics/model/forces.hpp"
#include "physics/stepping/lane_math.hpp"

#include <glm/geometric.hpp>

#include <cstdint>

namespace pl::fast {

// What the slide of one particle resting on one wall made of it (see slide_lane).
struct Slide {
    double x, y, z, vx, vy, vz;
    double drag_loss, wind_gain, friction_loss;
    bool ok;
};

// ParticleStepper::advance for a particle resting on the wall whose bit in the resting mask
// is `wall_bit` (one bit), if it stays on it, slides (or sticks) and reaches no other wall in
// the step, without branches so that it vectorises: the release test, then slide() for one
// wall, the same operations in the same order (fast_kernel_test checks the bits). `ok` is false
// where the particle is released, comes to a stop (an event) or slides into another wall; the
// generic path takes those. f: the particle's forces, filled in place by the caller.
template <class F>
inline Slide slide_lane(const F& f, const RoomBounds& room, double friction, double t0, double h, double r,
                        std::int64_t wall_bit, double px, double py, double pz, double pvx, double pvy, double pvz) {
    const std::uint64_t ax = (wall_bit & 0x03) != 0 ? ~std::uint64_t{0} : 0;
    const std::uint64_t ay = (wall_bit & 0x0c) != 0 ? ~std::uint64_t{0} : 0;
    const std::uint64_t az = (wall_bit & 0x30) != 0 ? ~std::uint64_t{0} : 0;
    const double n_sign = (wall_bit & 0x2a) != 0 ? -1.0 : 1.0;  // the walls at the room's maximum
    const Vec3 normal(pick(ax, n_sign, 0.0), pick(ay, n_sign, 0.0), pick(az, n_sign, 0.0));
    const Vec3 x(px, py, pz);
    Vec3 v(pvx, pvy, pvz);
    const Derivative d = f(x, v, t0);
    const bool released = (glm::dot(d.a, normal) > 0.0) | (glm::dot(v, normal) > 0.0);
    Vec3 a = d.a;
    double press = 0.0;
    const double an = glm::dot(a, normal);
    press -= an;
    a -= an * normal;
    v -= glm::dot(v, normal) * normal;
    const Vec3 v_free = v + h * a;
    const double jump = h * friction * press;
    const double speed = glm::length(v_free);
    const bool was_moving = (v.x != 0.0) | (v.y != 0.0) | (v.z != 0.0);
    const bool stuck = speed <= jump;
    const double keep = 1.0 - jump / speed;
    const Vec3 v_new(when(stuck, 0.0, v_free.x * keep), when(stuck, 0.0, v_free.y * keep),
                     when(stuck, 0.0, v_free.z * keep));
    const double friction_loss = 0.0 + 0.5 * (speed * speed - glm::dot(v_new, v_new));
    const double drag_loss = 0.0 + h * d.drag_power;
    const double wind_gain = 0.0 + h * d.wind_power;
    const bool still = (v_new.x == 0.0) & (v_new.y == 0.0) & (v_new.z == 0.0);
    const Vec3 end = x + h * (0.5 * (v + v_new));  // the mean velocity (ParticleStepper::slide)
    const bool end_inside = clear_of_walls(room, end, r);
    const Vec3 moved = clamp_inside(room, end, r);
    const Vec3 x_new(when(still, x.x, moved.x), when(still, x.y, moved.y), when(still, x.z, moved.z));
    const bool finite = all_finite(x_new.x, x_new.y, x_new.z, drag_loss, wind_gain) &
                        all_finite(friction_loss, 0.0, 0.0, 0.0, 0.0) & credible(v_new.x, v_new.y, v_new.z);
    return {x_new.x, x_new.y, x_new.z, v_new.x, v_new.y, v_new.z, drag_loss, wind_gain, friction_loss,
            static_cast<bool>(!released & !(was_moving & still) & (still | end_inside) & finite)};
}

}  // namespace pl::fast
