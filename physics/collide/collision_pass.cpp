#include "physics/collide/collision_pass.hpp"

#include "physics/collide/narrow_phase.hpp"
#include "physics/collide/particle_body.hpp"
#include "physics/collide/slices.hpp"
#include "physics/stepping/contact.hpp"
#include "physics/stepping/energy.hpp"
#include "physics/stepping/thread_pool.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>

namespace pl::collide {

void CollisionPass::move_to(ParticleState& s, const Model& m, std::uint32_t i, const Vec3& x) {
    if (!s.collision_work.empty())
        s.collision_work[i] += s.mass[i] * glm::dot(m.world.gravity, s.position(i) - x);
    s.set_position(i, x);
}

CollisionPass::CollisionPass(std::size_t particles)
    : start_(particles), start_velocity_(particles), start_spin_(particles), path_start_(particles), path_rate_(particles), path_time_(particles),
      strikes_(particles, 0), stamp_(particles, 0), touched_(particles, 0), listed_(particles, 0), row_(particles, 0),
      added_head_(particles, no_link), cover_of_(particles, 0), islands_(particles) {
    boxes_.resize(particles);
}

void CollisionPass::begin_step(const ParticleState& s, const Model& m, std::size_t threads) {
    // The start of the step: positions (the swept boxes; sleepers go back there) and, where the
    // contacts' work is booked from them (ContactSolver::hand_back: a ledger on an Euler method),
    // velocities and, in a scene with spin, spins. Scenes on the methods exact under a constant
    // force never read those (every collision scene keeps a ledger, so the Euler methods, the
    // default, still copy them: 2.4 MB a step at 1e5). Without spin the solver turns nothing.
    const bool velocities = ContactSolver::reads_start_velocities(s, m);
    const bool spins = velocities && spin_matters(m);
    for_ranges(s.size(), threads, [&](std::size_t begin, std::size_t end, std::size_t) {
        for (std::size_t i = begin; i < end; ++i) start_[i] = s.position(i);
        if (velocities)
            for (std::size_t i = begin; i < end; ++i) start_velocity_[i] = s.velocity(i);
        if (spins)
            for (std::size_t i = begin; i < end; ++i) start_spin_[i] = s.spin(i);
    });
}

void CollisionPass::build_boxes(const ParticleState& s, std::size_t threads) {
    // The boxes, and the farthest any moved along an axis (a maximum per task, then over the
    // tasks: the same on any number of threads), and the frozen particles counted. Each box is
    // tested against the pair cache's fat box as it is made (PairCache::watch).
    const std::size_t tasks = range_tasks(s.size(), threads);
    task_reach_.assign(tasks, 0.0);
    task_frozen_.assign(tasks, 0);
    const bool watch = pair_cache_.watch(tasks, s.size());
    const std::vector<std::uint8_t>& asleep = islands_.asleep();
    for_ranges(s.size(), threads, [&](std::size_t begin, std::size_t end, std::size_t task) {
        double reach = 0.0;
        std::size_t frozen = 0;
        for (std::size_t i = begin; i < end; ++i) {
            const Vec3 stop = s.position(i);
            const SweptBox b = box_around(start_[i], stop, s.radius[i]);
            double move = 0.0;
            for (int k = 0; k < 3; ++k) move = std::max(move, std::abs(stop[k] - start_[i][k]));
            boxes_.box[i] = b;
            boxes_.move[i] = static_cast<float>(move);
            reach = std::max(reach, move);
            frozen += s.frozen[i];
            if (watch && !s.frozen[i]) pair_cache_.check(task, static_cast<std::uint32_t>(i), b, asleep[i] != 0);
        }
        task_reach_[task] = reach;
        task_frozen_[task] = frozen;
    });
    boxes_.reach = *std::max_element(task_reach_.begin(), task_reach_.end());
    // The unfrozen ones take part: while none is frozen, that is every index, as last step (the
    // list is remade only when it changes: a serial pass over all particles each step, else).
    const bool none_frozen = std::all_of(task_frozen_.begin(), task_frozen_.end(), [](std::size_t f) { return f == 0; });
    if (none_frozen && boxes_.ids.size() == s.size()) return;
    boxes_.ids.clear();
    for (std::uint32_t i = 0; i < s.size(); ++i)
        if (!s.frozen[i]) boxes_.ids.push_back(i);
    ids_changed_ = true;
}

double CollisionPass::impact_speed(const Model& m, double h) {
    return 2.0 * glm::length(m.world.gravity) * h;
}

bool CollisionPass::find_hit(const ParticleState& s, const Pair& p, double h, bool spin, double impact, Hit& hit) const {
    // A hit needs its contact point to close faster than `impact` along the normal, and
    // |u . n| <= |u| <= |v_b - v_a| + |w_a| r_a + |w_b| r_b whatever the normal: a pair slower
    // than that is none, and skips the root (most pairs of a settling pile rest). The margin
    // covers the round-off of u . n, so the skip changes no result.
    if (impact > 0.0) {
        double bound = glm::length(s.velocity(p.b) - s.velocity(p.a));
        if (spin) bound += glm::length(s.spin(p.a)) * s.radius[p.a] + glm::length(s.spin(p.b)) * s.radius[p.b];
        if (bound < impact * (1.0 - 1e-9)) return false;
    }
    const double t0 = std::max(path_time_[p.a], path_time_[p.b]);
    const Vec3 d = at(p.b, t0) - at(p.a, t0);
    const Vec3 w = path_rate_[p.b] - path_rate_[p.a];
    const double s_hit = time_of_impact(d, w, s.radius[p.a] + s.radius[p.b], h - t0);
    if (s_hit < 0.0) return false;
    const Vec3 gap = d + s_hit * w;
    const double len = glm::length(gap);
    if (!(len > 0.0)) return false;  // concentric: no normal to push along
    hit = {t0 + s_hit, p.a, p.b, gap / len, strikes_[p.a], strikes_[p.b]};
    // An impact needs a contact point that closes (its velocity, not the path's rate) faster than
    // `impact`; slower ones are the contact solver's.
    return glm::dot(contact_velocity(body_of(s, p.a), body_of(s, p.b), hit.n, spin), hit.n) < -impact;
}

void CollisionPass::touch(std::uint32_t i) {
    if (touched_[i]) return;
    touched_[i] = 1;
    moved_.push_back(i);
}

double CollisionPass::strike(ParticleState& s, std::uint32_t i, double t, const Vec3& dv, const Vec3& dw, bool spin) {
    path_start_[i] = at(i, t);
    path_time_[i] = t;
    path_rate_[i] += dv;
    const double e0 = motion_energy(s, i);
    s.set_velocity(i, s.velocity(i) + dv);
    if (spin) s.set_spin(i, s.spin(i) + dw);
    // The solver books its work from the start's velocity and spin, with the impacts' added
    // (an impact's work is booked where it is struck: the solver's would count its dv twice).
    start_velocity_[i] += dv;
    if (spin) start_spin_[i] += dw;
    ++strikes_[i];
    touch(i);
    return motion_energy(s, i) - e0;
}

void CollisionPass::resolve(ParticleState& s, const Model& m, const Hit& hit, bool spin) {
    const CollisionSettings& c = m.collisions;
    const ImpulseResult r = sphere_impulse(body_of(s, hit.a), body_of(s, hit.b), hit.n, c.restitution, c.friction, spin);
    for (const auto& [i, dv, dw] : {std::tuple{hit.a, r.dv_a, r.dw_a}, std::tuple{hit.b, r.dv_b, r.dw_b}}) {
        const double gained = strike(s, i, hit.t, dv, dw, spin);
        if (!s.collision_work.empty()) s.collision_work[i] += gained;
    }
}

void CollisionPass::hold_sleepers(ParticleState& s) {
    // The kernel stepped every particle; a sleeping one goes back to where it slept, at rest, as
    // if the step had not been taken (so nothing is booked: no energy changed).
    if (islands_.asleep_count() == 0) return;
    const std::vector<std::uint8_t>& asleep = islands_.asleep();
    for (std::uint32_t i = 0; i < s.size(); ++i) {
        if (!asleep[i]) continue;
        s.set_position(i, start_[i]);
        s.set_velocity(i, Vec3(0.0));
        s.set_spin(i, Vec3(0.0));
    }
}

void CollisionPass::keep_rest_on_walls(ParticleState& s, double impact) {
    // A particle resting on a wall that the contacts left moving into it as fast as an impact is
    // struck: the wall holds it no longer, so that the kernel's next step bounces it (with the
    // walls' restitution and its ledger) instead of taking the normal velocity away unrecorded.
    // One left moving away from it as fast as an impact (struck off it: a small ball striking a
    // big one low) keeps that velocity: the kernel's next step lifts it off (release_walls, a lift
    // event). One left moving into it or away from it slower than an impact keeps resting (the
    // solver's round-off, not a lift or a bounce): that normal velocity is taken away here, and
    // its energy booked as the contacts' work. (Struck away, it was held at rest above the floor
    // where its path had carried it, gliding on nothing.)
    for (const std::uint32_t i : moved_) {
        if (!s.resting[i]) continue;
        for (int w = 0; w < wall_count; ++w) {
            if (!(s.resting[i] & (1u << w))) continue;
            const Vec3 n = RoomBounds::inward_normal(w), v = s.velocity(i);
            const double away = glm::dot(v, n);
            if (away <= -impact) {
                s.resting[i] &= static_cast<std::uint8_t>(~(1u << w));
            } else if (away != 0.0 && away < impact) {
                s.set_velocity(i, v - away * n);
                if (!s.collision_work.empty()) s.collision_work[i] -= 0.5 * s.inertial_mass[i] * away * away;
            }
        }
    }
}

void CollisionPass::append_hits(const ParticleState& s, double h, bool spin, double impact, std::size_t threads) {
    // Each queued pair's first contact along the current paths, appended to hits_; threaded in
    // slices of the queue, joined in order (the same hits on any number of threads).
    append_in_slices(queue_.size(), threads, 4096, slice_hits_, hits_,
                     [&](std::size_t begin, std::size_t end, std::vector<Hit>& out) {
                         Hit hit;
                         for (std::size_t k = begin; k < end; ++k)
                             if (find_hit(s, pairs_[queue_[k]], h, spin, impact, hit)) out.push_back(hit);
                     });
}

void CollisionPass::list_pair_particles() {
    // The particles of the pairs, each once, in order of first appearance. A pile's ball is in a
    // dozen pairs: the passes over the pairs' particles (their paths, their clamp to the room)
    // touched its scattered state a dozen times a step, from main memory at 1e5; the flags are a
    // byte a particle, which the caches hold.
    pair_particles_.clear();
    for (const Pair& p : pairs_)
        for (const std::uint32_t i : {p.a, p.b})
            if (!listed_[i]) {
                listed_[i] = 1;
                pair_particles_.push_back(i);
            }
    for (const std::uint32_t i : pair_particles_) listed_[i] = 0;
}

void CollisionPass::index_pairs() {
    // Each paired particle's pairs, in compressed rows: particle i's row r = row_[i] runs from
    // pair_start_[r] to pair_start_[r + 1] in pair_of_, its pairs in increasing order. Rows only
    // for the particles in some pair (pair_particles_: row r is its r-th): the cost follows the
    // pairs, not the particles (a row per particle made this a serial pass over all of them).
    // Rows of particles in no pair are stale and never read.
    const auto rows = static_cast<std::uint32_t>(pair_particles_.size());
    rows_ = rows;
    broad_pairs_ = pairs_.size();
    for (std::uint32_t r = 0; r < rows; ++r) row_[pair_particles_[r]] = r;
    pair_start_.assign(std::size_t{rows} + 1, 0);
    for (const Pair& p : pairs_) {
        ++pair_start_[row_[p.a]];
        ++pair_start_[row_[p.b]];
    }
    std::uint32_t sum = 0;
    for (std::uint32_t& start : pair_start_) sum += std::exchange(start, sum);  // counts to starts
    pair_fill_.assign(pair_start_.begin(), pair_start_.end() - 1);
    pair_of_.resize(2 * pairs_.size());
    for (std::uint32_t k = 0; k < pairs_.size(); ++k) {
        pair_of_[pair_fill_[row_[pairs_[k].a]]++] = k;
        pair_of_[pair_fill_[row_[pairs_[k].b]]++] = k;
    }
    pair_queued_.assign(pairs_.size(), 0);
}

void CollisionPass::queue_pairs_of(const std::vector<std::uint32_t>& resolved, std::uint32_t event) {
    // Only a pair with a particle whose path the impact changed can hold a new first contact: the
    // others keep their paths, and their first contacts are in the queue already. A pair of the
    // two struck particles is queued once (`event` stamps it).
    queue_.clear();
    auto queue = [&](std::uint32_t pair) {
        if (pair_queued_[pair] == event) return;
        pair_queued_[pair] = event;
        queue_.push_back(pair);
    };
    for (const std::uint32_t i : resolved) {
        if (has_row(i))
            for (std::uint32_t k = pair_start_[row_[i]]; k < pair_start_[row_[i] + 1]; ++k) queue(pair_of_[k]);
        for_added_pairs_of(i, queue);
    }
}

bool CollisionPass::still_current(const Hit& hit) const {
    // Neither particle was struck since the hit was found (else its path bent: the hit is stale,
    // and the particle's pairs were searched again), and neither has used up its strikes.
    const bool a_current = strikes_[hit.a] == hit.strikes_a && hit.strikes_a < max_strikes;
    return a_current && (hit.is_wall() || (strikes_[hit.b] == hit.strikes_b && hit.strikes_b < max_strikes));
}

void CollisionPass::queue_hits(std::size_t from) {
    for (std::size_t k = from + 1; k <= hits_.size(); ++k)
        std::push_heap(hits_.begin(), hits_.begin() + static_cast<std::ptrdiff_t>(k), later);
}

std::uint64_t CollisionPass::resolve_impacts(ParticleState& s, const Model& m, double h, double impact,
                                             std::size_t threads) {
    for (const std::uint32_t i : pair_particles_) {
        path_start_[i] = start_[i];
        path_time_[i] = 0.0;
        path_rate_[i] = (s.position(i) - start_[i]) / h;
    }
    const bool spin = spin_matters(m);
    queue_.resize(pairs_.size());
    for (std::uint32_t k = 0; k < pairs_.size(); ++k) queue_[k] = k;  // first: every pair
    hits_.clear();
    append_hits(s, h, spin, impact, threads);
    if (hits_.empty()) return 0;
    index_pairs();
    std::make_heap(hits_.begin(), hits_.end(), later);
    std::uint64_t impulses = 0;
    for (std::uint32_t event = 1; !hits_.empty();) {
        std::pop_heap(hits_.begin(), hits_.end(), later);
        const Hit c = hits_.back();
        hits_.pop_back();
        if (!still_current(c)) continue;
        resolved_.assign(1, c.a);
        if (c.is_wall()) {
            if (!resolve_wall(s, m, c, impact)) continue;
        } else {
            resolve(s, m, c, spin);
            resolved_.push_back(c.b);
            ++impulses;
        }
        // The struck particles' paths bent at c.t: their pairs' first contacts from then on (with
        // the particles a new path reaches outside its swept box paired first), and the wall
        // each now runs into.
        for (const std::uint32_t i : resolved_) reach_new_path(s, i, h);
        queue_pairs_of(resolved_, event++);
        const std::size_t from = hits_.size();
        append_hits(s, h, spin, impact, threads);
        find_wall_hits(s, m, h, impact);
        queue_hits(from);
    }
    end_reach();
    for (const std::uint32_t i : moved_)
        if (strikes_[i] >= max_strikes) caught_.push_back(i);
    for (const std::uint32_t i : moved_) strikes_[i] = 0;  // only struck particles carry strikes
    const RoomBounds room(m.room);
    for (const std::uint32_t i : moved_) move_to(s, m, i, room.clamp_inside(at(i, h), s.radius[i]));
    return impulses;
}

std::uint64_t CollisionPass::end_step(ParticleState& s, const Model& m, double h, std::size_t threads) {
    for (const std::uint32_t i : moved_) touched_[i] = 0;
    moved_.clear();
    wall_bounces_.clear();
    hold_sleepers(s);
    build_boxes(s, threads);
    // Pairs of two sleeping particles are left out: with every particle asleep there are none,
    // and a pile asleep costs no broad phase at all.
    const std::vector<std::uint8_t>& asleep = islands_.asleep();
    if (std::any_of(boxes_.ids.begin(), boxes_.ids.end(), [&](std::uint32_t i) { return !asleep[i]; })) {
        pair_cache_.find_pairs_watched(boxes_, pairs_, asleep.data(), threads, !ids_changed_);
        ids_changed_ = false;
    } else {
        pairs_.clear();
    }
    list_pair_particles();
    const double impact = impact_speed(m, h);
    caught_.clear();  // filled by resolve_impacts
    const std::uint64_t impacts = pairs_.empty() ? 0 : resolve_impacts(s, m, h, impact, threads);
    // Then the resting contacts, among the pairs and with the walls, and who sleeps next step.
    solver_.gather(s, m, pairs_, moved_, caught_, asleep, h, impact, threads);
    resting_ = solver_.solve(s, m, h, start_velocity_, start_spin_, pair_cache_.grid().order(), threads);
    for (const SolverContact& c : solver_.contacts()) {
        if (!c.active) continue;
        touch(c.a);
        if (!c.is_wall()) touch(c.b);
    }
    keep_rest_on_walls(s, impact);
    // The solver may have moved a ball into a wall (it never pushes one away: a ball moving off a
    // wall and stopped by a heavy one behind it ends past the wall): back inside before the
    // overlaps are measured, so that the ball behind it is the one moved back.
    const RoomBounds room(m.room);
    for (const std::uint32_t i : moved_) move_to(s, m, i, room.clamp_inside(s.position(i), s.radius[i]));
    remove_overlaps(s, m);  // keeps every ball it moves inside the room
    // Each paired particle once (pair_particles_ lists each once): threaded, the same bits.
    for_ranges(pair_particles_.size(), threads, [&](std::size_t begin, std::size_t end, std::size_t) {
        for (std::size_t k = begin; k < end; ++k) {
            const std::uint32_t i = pair_particles_[k];
            move_to(s, m, i, room.clamp_inside(s.position(i), s.radius[i]));
        }
    });
    // The one place islands wake in a step: every particle struck by an impact or in an active
    // contact (a sleeping one touched by an awake one) is in moved_.
    for (const std::uint32_t i : moved_)
        if (islands_.asleep()[i]) islands_.wake(i);
    islands_.update(s, solver_.contacts(), m.contact.rest_speed, h, threads);
    crossings_.clear();
    find_crossings(pairs_, start_, s, islands_.asleep(), apart_share, crossings_);
    return impacts;
}

}  // namespace pl::collide
