#include "physics/collide/collision_pass.hpp"

#include "physics/collide/narrow_phase.hpp"
#include "physics/stepping/contact.hpp"
#include "physics/stepping/energy.hpp"

#include <algorithm>
#include <tuple>

namespace pl::collide {
namespace {

Body body_of(const ParticleState& s, std::uint32_t i) {
    return {s.velocity(i), s.spin(i), s.mass[i], s.radius[i], s.inertia[i]};
}

double motion_energy(const ParticleState& s, std::uint32_t i) {
    return kinetic_energy(s.mass[i], s.velocity(i)) + spin_energy(s.mass[i], s.radius[i], s.inertia[i], s.spin(i));
}

}  // namespace

CollisionPass::CollisionPass(std::size_t particles)
    : start_(particles), path_start_(particles), path_rate_(particles), path_time_(particles),
      stamp_(particles, 0), touched_(particles, 0) {
    boxes_.resize(particles);
}

void CollisionPass::begin_step(const ParticleState& s) {
    for (std::size_t i = 0; i < s.size(); ++i) start_[i] = s.position(i);
}

void CollisionPass::build_boxes(const ParticleState& s) {
    boxes_.ids.clear();
    for (std::uint32_t i = 0; i < s.size(); ++i) {
        if (s.frozen[i]) continue;
        const Vec3 end = s.position(i);
        const double r = s.radius[i];
        for (int k = 0; k < 3; ++k) {
            boxes_.lo[k][i] = std::min(start_[i][k], end[k]) - r;
            boxes_.hi[k][i] = std::max(start_[i][k], end[k]) + r;
        }
        boxes_.ids.push_back(i);
    }
}

bool CollisionPass::find_hit(const ParticleState& s, const Pair& p, double h, bool spin, Hit& hit) const {
    const double t0 = std::max(path_time_[p.a], path_time_[p.b]);
    const Vec3 d = at(p.b, t0) - at(p.a, t0);
    const Vec3 w = path_rate_[p.b] - path_rate_[p.a];
    const double s_hit = time_of_impact(d, w, s.radius[p.a] + s.radius[p.b], h - t0);
    if (s_hit < 0.0) return false;
    const Vec3 gap = d + s_hit * w;
    const double len = glm::length(gap);
    if (!(len > 0.0)) return false;  // concentric: no normal to push along
    hit = {t0 + s_hit, p.a, p.b, gap / len};
    // The impulse acts only on a contact point that closes (its velocity, not the path's rate).
    return glm::dot(contact_velocity(body_of(s, p.a), body_of(s, p.b), hit.n, spin), hit.n) < 0.0;
}

void CollisionPass::touch(std::uint32_t i) {
    if (touched_[i]) return;
    touched_[i] = 1;
    moved_.push_back(i);
}

void CollisionPass::resolve(ParticleState& s, const Model& m, const Hit& hit, bool spin) {
    const CollisionSettings& c = m.collisions;
    const ImpulseResult r = sphere_impulse(body_of(s, hit.a), body_of(s, hit.b), hit.n, c.restitution, c.friction, spin);
    for (const auto& [i, dv, dw] : {std::tuple{hit.a, r.dv_a, r.dw_a}, std::tuple{hit.b, r.dv_b, r.dw_b}}) {
        path_start_[i] = at(i, hit.t);
        path_time_[i] = hit.t;
        path_rate_[i] += dv;
        const double e0 = motion_energy(s, i);
        s.set_velocity(i, s.velocity(i) + dv);
        if (spin) s.set_spin(i, s.spin(i) + dw);
        if (!s.collision_work.empty()) s.collision_work[i] += motion_energy(s, i) - e0;
        touch(i);
    }
}

void CollisionPass::remove_overlaps(ParticleState& s) {
    // Inverse-mass weighted positional correction (Catto's "split impulse" idea without the
    // velocity: only positions move), a bounded share of each overlap per step, in pair order.
    for (const Pair& p : pairs_) {
        const Vec3 d = s.position(p.b) - s.position(p.a);
        const double contact = s.radius[p.a] + s.radius[p.b];
        const double len = glm::length(d);
        const double overlap = contact - len - allowed_overlap * contact;
        if (!(overlap > 0.0) || !(len > 0.0)) continue;
        const double inv_a = 1.0 / s.mass[p.a], inv_b = 1.0 / s.mass[p.b];
        const double correction = std::min(correction_share * overlap, max_correction * contact);
        const Vec3 push = (correction / (len * (inv_a + inv_b))) * d;
        s.set_position(p.a, s.position(p.a) - inv_a * push);
        s.set_position(p.b, s.position(p.b) + inv_b * push);
    }
}

std::uint64_t CollisionPass::end_step(ParticleState& s, const Model& m, double h) {
    for (const std::uint32_t i : moved_) touched_[i] = 0;
    moved_.clear();
    build_boxes(s);
    broad_.find_pairs(boxes_, pairs_);
    if (pairs_.empty()) return 0;
    for (const Pair& p : pairs_)
        for (const std::uint32_t i : {p.a, p.b}) {
            path_start_[i] = start_[i];
            path_time_[i] = 0.0;
            path_rate_[i] = (s.position(i) - start_[i]) / h;
        }
    const bool spin = spin_matters(m);
    std::uint64_t impulses = 0;
    for (std::uint32_t pass = 1; pass <= static_cast<std::uint32_t>(max_passes); ++pass) {
        hits_.clear();
        Hit hit;
        for (const Pair& p : pairs_)
            if (find_hit(s, p, h, spin, hit)) hits_.push_back(hit);
        if (hits_.empty()) break;
        std::sort(hits_.begin(), hits_.end(), [](const Hit& x, const Hit& y) {
            return x.t != y.t ? x.t < y.t : (x.a != y.a ? x.a < y.a : x.b < y.b);
        });
        for (const Hit& c : hits_) {
            if (stamp_[c.a] == pass || stamp_[c.b] == pass) continue;  // its path changed: next pass
            stamp_[c.a] = stamp_[c.b] = pass;
            resolve(s, m, c, spin);
            ++impulses;
        }
    }
    for (const std::uint32_t i : moved_) stamp_[i] = 0;  // only resolved particles carry a stamp
    const RoomBounds room(m.room);
    for (const std::uint32_t i : moved_) s.set_position(i, room.clamp_inside(at(i, h), s.radius[i]));
    remove_overlaps(s);
    for (const Pair& p : pairs_)
        for (const std::uint32_t i : {p.a, p.b}) s.set_position(i, room.clamp_inside(s.position(i), s.radius[i]));
    return impulses;
}

}  // namespace pl::collide
