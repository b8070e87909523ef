// The overlap removal of the collision pass (CollisionPass, collision_pass.hpp): pairs left in
// each other after the impacts and the contact solver are pushed apart on positions, and a pair
// a step drove deep is noted for the collision_overlap warning.
#include "physics/collide/collision_pass.hpp"

#include <algorithm>

namespace pl::collide {

double CollisionPass::shift_inside(ParticleState& s, const Model& m, const RoomBounds& room, std::uint32_t i, const Vec3& by) {
    const double wanted = glm::length(by);
    if (!(wanted > 0.0)) return 0.0;
    const Vec3 from = s.position(i);
    move_to(s, m, i, room.clamp_inside(from + by, s.radius[i]));
    return glm::dot(s.position(i) - from, by) / wanted;
}

void CollisionPass::remove_overlaps(ParticleState& s, const Model& m) {
    // Inverse-mass weighted positional correction (Catto's "split impulse" idea without the
    // velocity: only positions move), a bounded share of each overlap per step, in pair order.
    // Sleeping pairs stay where they are. The potential energy a move gives is contact work.
    // Concentric centres (two balls placed at one point) have no normal: they are opened "up",
    // against gravity (+y without it), b above a, as a ball put on top of another would rest.
    // Where the solver propagated shock (very unequal masses, contact_shock.cpp) the pairs are
    // taken from the lowest up, and a pair that carries weight moves its upper ball alone (split
    // by inverse mass, a light ball between two heavy ones was pushed up by one pair and down by
    // the next, and the heavy balls stayed sunk into it); any other pair whose one ball is nearer
    // a wall it is pressed into (the solver's anchor levels) moves the other ball alone.
    const double g = glm::length(m.world.gravity);
    const Vec3 up = g > 0.0 ? -m.world.gravity / g : Vec3(0.0, 1.0, 0.0);
    const std::vector<std::uint8_t>& asleep = islands_.asleep();
    deep_overlaps_.clear();
    const bool shock = solver_.propagated_shock();
    const RoomBounds room(m.room);
    auto open = [&](const Pair& p) {
        if (asleep[p.a] && asleep[p.b]) return;
        const Vec3 d = s.position(p.b) - s.position(p.a);
        const double contact = s.radius[p.a] + s.radius[p.b];
        const double len = glm::length(d);
        const double overlap = contact - len - allowed_overlap * contact;
        if (!(overlap > 0.0)) return;
        note_deep_overlap(p, contact, len);
        double inv_a = 1.0 / s.inertial_mass[p.a], inv_b = 1.0 / s.inertial_mass[p.b];
        if (shock && len > 0.0) {
            if (g > 0.0 && carries_weight(d, up, len, ContactSolver::shock_least_rise)) {
                (glm::dot(d, up) > 0.0 ? inv_a : inv_b) = 0.0;  // the lower ball holds still
            } else {
                // The ball nearer the wall it is pressed into holds still (contact_shock.cpp).
                const std::uint32_t level_a = solver_.anchor_level(p.a), level_b = solver_.anchor_level(p.b);
                if (level_a != level_b) (level_a < level_b ? inv_a : inv_b) = 0.0;
            }
        }
        const double correction = std::min(correction_share * overlap, max_correction * contact);
        const Vec3 along = len > 0.0 ? d / len : up;  // from a to b
        // Each ball its share, kept inside the room; what a wall keeps one ball from taking the
        // other takes (a light ball against a wall: the heavy ball behind it is moved back,
        // where the light ball's share was lost to the wall and the overlap grew step by step).
        const double share_a = correction * inv_a / (inv_a + inv_b);
        const double taken_a = shift_inside(s, m, room, p.a, -share_a * along);
        const double taken_b = shift_inside(s, m, room, p.b, (correction - taken_a) * along);
        if (taken_a + taken_b < correction) shift_inside(s, m, room, p.a, -(correction - taken_a - taken_b) * along);
        for (const std::uint32_t i : {p.a, p.b})
            if (stamp_[i] != corrected) {
                stamp_[i] = corrected;
                corrected_.push_back(i);
            }
    };
    if (shock) {
        order_bottom_up(s, up, pairs_, [](const Pair&) { return true; }, bottom_up_);
        for (const auto& [height, k] : bottom_up_) open(pairs_[k]);
    } else {
        for (const Pair& p : pairs_) open(p);
    }
    for (const std::uint32_t i : corrected_) stamp_[i] = 0;
    corrected_.clear();
}

void CollisionPass::note_deep_overlap(const Pair& p, double contact, double distance) {
    // Only the step's own motion counts: a pair the step drove in from less than half the limit
    // (apart at its start, or touching and driven in by a ball behind it), or deeper by more than
    // half the limit than it began (a chain driven into a wall sinks over several steps), neither of whose balls
    // this removal has moved yet (opening a crowd pushes balls into their neighbours for a step);
    // never an emitter's overlaps, deep from the start, being opened.
    const double share = (contact - distance) / contact;
    if (share > warn_overlap && stamp_[p.a] != corrected && stamp_[p.b] != corrected) {
        const double start_share = 1.0 - glm::distance(start_[p.a], start_[p.b]) / contact;
        if (start_share < apart_share || share > start_share + apart_share)
            deep_overlaps_.push_back({p.a, p.b, share});
    }
}

}  // namespace pl::collide
