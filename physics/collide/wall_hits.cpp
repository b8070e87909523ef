// The walls among the impacts (collision_pass.hpp). The kernel meets the walls on its own path,
// once a step; an impact bends a particle's path after that. A light ball pressed on the floor by
// a heavy one bounces between the two many times in an instant: met only by the kernel, it takes
// one floor bounce and one blow a step, and a column of unlike masses sinks into its bottom ball,
// the balls passing through each other; a ball struck toward a near wall would be held against
// it at the step's end, still moving into it, and bounce a step late. So a particle the pass
// strikes whose new path reaches a wall before the step ends (or touches it already), moving
// into it faster than an impact, takes that wall hit in the queue, among the pairs' hits in time
// order, with the walls' restitution law and friction (the kernel's impact: Newton's law on the
// normal speed, Coulomb friction that at most stops the slip, the spin's share where
// contact.spin couples it) and the walls' ledger lines (bounce and friction losses).
#include "physics/collide/collision_pass.hpp"

#include "physics/collide/narrow_phase.hpp"
#include "physics/collide/particle_body.hpp"
#include "physics/model/restitution.hpp"
#include "physics/stepping/contact.hpp"

#include <limits>

namespace pl::collide {

void CollisionPass::find_wall_hits(const ParticleState& s, const Model& m, double h, double impact) {
    // The first wall each just-struck particle's path reaches in the step (or touches),
    // moving into it faster than an impact (slower contacts are the solver's).
    const RoomBounds room(m.room);
    for (const std::uint32_t i : resolved_) {
        Hit first{h, i, 0, Vec3(0.0)};
        bool found = false;
        for (int w = 0; w < wall_count; ++w) {
            const Vec3 inward = RoomBounds::inward_normal(w);
            if (!(-glm::dot(s.velocity(i), inward) > impact)) continue;
            const double gap = room.distance(w, path_start_[i], s.radius[i]);
            const double rate = glm::dot(path_rate_[i], inward);  // < 0: the path runs into it
            double t = path_time_[i];
            if (gap > 0.0) {
                if (!(rate < 0.0)) continue;
                t += gap / -rate;
            }
            if (t > first.t || (found && t == first.t)) continue;
            first = {t, i, wall_hit + static_cast<std::uint32_t>(w), -inward, strikes_[i], 0};
            found = true;
        }
        if (found) hits_.push_back(first);
    }
}

bool CollisionPass::resolve_wall(ParticleState& s, const Model& m, const Hit& hit, double impact) {
    // The wall as a body that does not move (infinite mass and moment): sphere_impulse then is
    // the kernel's wall impact, restitution from the walls' law at this normal speed.
    const std::uint32_t i = hit.a;
    const auto wall = static_cast<int>(hit.b - wall_hit);
    const double speed_in = glm::dot(s.velocity(i), hit.n);
    const ContactSettings c = at_impact_speed(m.contact, speed_in);
    constexpr double infinite = std::numeric_limits<double>::infinity();
    const Body still{Vec3(0.0), Vec3(0.0), infinite, 0.0, infinite};
    const ImpulseResult r = sphere_impulse(body_of(s, i), still, hit.n, c.restitution, c.friction, m.contact.spin);
    if (!r.applied) return false;
    const double speed_before = glm::length(s.velocity(i));
    const double lost = -strike(s, i, hit.t, r.dv_a, r.dw_a, m.contact.spin);
    // The walls' ledger lines, as the kernel books a bounce: the normal speed's loss, the rest
    // (the slip's) to friction.
    const double bounce = 0.5 * s.inertial_mass[i] * speed_in * speed_in * (1.0 - c.restitution * c.restitution);
    s.dissipated_bounce[i] += bounce;
    s.dissipated_friction[i] += lost - bounce;
    wall_bounces_.push_back(
        {hit.t, i, static_cast<std::int8_t>(wall), EventKind::bounce, speed_before, glm::length(s.velocity(i))});
    // Bounced off faster than an impact, it no longer rests on that wall.
    if (c.restitution * speed_in > impact) s.resting[i] &= static_cast<std::uint8_t>(~(1u << wall));
    return true;
}

}  // namespace pl::collide
