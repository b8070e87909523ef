// The collision pass a Simulation with collisions enabled runs after each step of its particles
// (walls already handled): it puts sleeping particles back where they slept, finds the pairs that
// met during the step and resolves the impacts at their time of impact, hands the slow, lasting
// contacts (and the walls under them) to the contact solver (contact_solver.hpp), pushes apart
// pairs left overlapping, and lets still islands fall asleep (sleep_islands.hpp).
//
// Impacts: each particle's path over the step is taken as linear from where it started to where
// the step put it. The impacts are resolved one at a time in the order of their times, as an
// event-driven simulation of hard spheres does (Alder & Wainwright, J. Chem. Phys. 31, 459, 1959;
// Rapaport, "The Art of Molecular Dynamics Simulation", 2004, ch. 14): every candidate pair's first
// contact goes in a queue ordered by (time, a, b); the earliest is taken, the pair takes its
// impulse there and moves on with its new velocity for the rest of the step, and the first
// contacts of every pair of the two struck particles are found again from that time on. A hit
// found before one of its particles was struck again is stale and passed over (each hit carries
// its particles' strike counts). So no pair is resolved out of time order, and a fast pair cannot
// pass through each other whatever the step. A struck particle that lies against a wall and now
// moves into it takes that wall hit in the queue too (wall_hits.cpp). The first search runs
// threaded, but every order is fixed and the impulses are applied on one thread: the result is
// the same bits on any number of threads.
// Everything the pass changes (velocities, spins, positions) is booked in each particle's
// collision work, so the energy ledger's residual is the stepping method's own error.
#pragma once

#include "physics/collide/pair_cache.hpp"
#include "physics/collide/pair_crossings.hpp"
#include "physics/collide/contact_solver.hpp"
#include "physics/collide/sleep_islands.hpp"
#include "physics/model/scene.hpp"
#include "physics/stepping/contact.hpp"
#include "physics/stepping/events.hpp"
#include "physics/stepping/particle_state.hpp"

#include <algorithm>
#include <cstdint>
#include <tuple>
#include <vector>

namespace pl::collide {

class CollisionPass {
public:
    // At most this many impacts per particle per step (a ball caught between a heavy one and a
    // wall, or an inelastic collapse, would take endlessly many); its contacts still closing
    // after them are the contact solver's, or found again at the start of the next step.
    static constexpr std::uint32_t max_strikes = 64;
    // Overlap removal: the share of an overlap corrected per step, at most max_correction of the
    // pair's contact distance per step (deep overlaps, e.g. from an emitter, open over several
    // steps instead of throwing particles), and the overlap left alone (as a fraction of the
    // contact distance), so that resting contacts do not jitter.
    static constexpr double correction_share = 0.8;
    static constexpr double max_correction = 0.2;
    static constexpr double allowed_overlap = 1e-4;
    // A pair the step drove past this share of its contact distance, from less than half of it or
    // deeper by more than half of it than it began, is reported (deep_overlaps()): a meeting the pass could not follow (a ball that struck a
    // wall and another ball in one step, whose path was not straight; a light ball a heavy one
    // drove into a wall faster than the solver could stop it); never a settling pile (below 1%)
    // or an emitter's overlaps being opened (deep from the start).
    static constexpr double warn_overlap = 0.1;
    // A pair counts as apart at a step's start while it overlaps by less than this share of its
    // contact distance (half the limit): the overlap warning's and the crossing check's start.
    static constexpr double apart_share = 0.5 * warn_overlap;
    // The skin, in radii, around a struck particle's new path when the particles it may reach
    // are looked up (path_reach.cpp).
    static constexpr double reach_skin = 0.02;

    explicit CollisionPass(std::size_t particles);

    // Remembers where each particle starts the step (on up to `threads` threads).
    void begin_step(const ParticleState& s, const Model& m, std::size_t threads = 1);
    // Resolves the collisions of the step of length h just taken (s holds its end state). Returns
    // the number of impacts resolved; `moved()` lists the particles whose velocity changed. The
    // broad phase and the search for impacts run on up to `threads` threads; the impulses, the
    // contact solver and the islands on the calling thread, in a fixed order: the same bits on
    // any number of threads.
    std::uint64_t end_step(ParticleState& s, const Model& m, double h, std::size_t threads = 1);
    // Wakes the island of particle i (its velocity was set from outside).
    void wake(std::uint32_t i) { islands_.wake(i); }

    // Pairs closing slower than this at their contact point are resting contacts (the contact
    // solver's, without restitution); faster ones are impacts. It is what gravity adds to a
    // closing speed in two steps: a pile's weight is never bounced, and without gravity every
    // closing pair is an impact (an elastic gas keeps its energy exactly).
    static double impact_speed(const Model& m, double h);

    const std::vector<std::uint32_t>& moved() const { return moved_; }
    bool moved(std::uint32_t i) const { return touched_[i] != 0; }  // i is in moved()
    const std::vector<Pair>& candidates() const { return pairs_; }
    // Pairs the impacts added since the start: struck particles whose new paths left the swept
    // boxes they were paired by (path_reach.cpp).
    std::uint64_t added_pairs() const { return added_total_; }
    const PairCache& pair_cache() const { return pair_cache_; }
    bool propagated_shock() const { return solver_.propagated_shock(); }  // last step (contact_shock.cpp)
    const std::vector<SolverContact>& contacts() const { return solver_.contacts(); }
    const std::vector<std::uint8_t>& asleep() const { return islands_.asleep(); }
    // This step: the particles of a pile that fell asleep (SleepIslands::fell_asleep).
    const std::vector<std::uint32_t>& fell_asleep() const { return islands_.fell_asleep(); }
    std::size_t asleep_count() const { return islands_.asleep_count(); }
    std::uint64_t resting_contacts() const { return resting_; }  // loaded contacts, last step
    // The last step's pairs left overlapping past warn_overlap (before the overlap removal), by
    // particle a < b and the overlap as a share of their contact distance.
    struct DeepOverlap {
        std::uint32_t a, b;
        double share;
    };
    const std::vector<DeepOverlap>& deep_overlaps() const { return deep_overlaps_; }
    // The last step's pairs that crossed each other (pair_crossings.hpp).
    const std::vector<PairCrossing>& crossings() const { return crossings_; }
    // The last step's wall hits taken among the impacts (wall_hits.cpp), as bounce events
    // whose t is the time into the step.
    const std::vector<Event>& wall_bounces() const { return wall_bounces_; }

private:
    // A hit of particles a and b, or of particle a with wall w (b = wall_hit + w), at time t of
    // the step; n from a to b (into the wall); the strike counts of a and b when it was found.
    struct Hit {
        double t;
        std::uint32_t a, b;
        Vec3 n;
        std::uint32_t strikes_a = 0, strikes_b = 0;
        bool is_wall() const { return b >= wall_hit; }
    };
    // The queue's order: x comes after y (a min-heap on (t, a, b), the strike counts last).
    static bool later(const Hit& x, const Hit& y) {
        return std::tie(x.t, x.a, x.b, x.strikes_a, x.strikes_b) > std::tie(y.t, y.a, y.b, y.strikes_a, y.strikes_b);
    }
    bool still_current(const Hit& hit) const;
    static constexpr std::uint32_t wall_hit = 0xfffffff0u;
    void build_boxes(const ParticleState& s, std::size_t threads);
    // The box around a sphere of radius r moving from a to b.
    static SweptBox box_around(const Vec3& a, const Vec3& b, double r) {
        SweptBox box;
        for (int k = 0; k < 3; ++k) {
            box.lo[k] = std::min(a[k], b[k]) - r;
            box.hi[k] = std::max(a[k], b[k]) + r;
        }
        return box;
    }
    Vec3 at(std::uint32_t i, double t) const { return path_start_[i] + (t - path_time_[i]) * path_rate_[i]; }
    bool find_hit(const ParticleState& s, const Pair& p, double h, bool spin, double impact, Hit& hit) const;
    void hold_sleepers(ParticleState& s);
    void append_hits(const ParticleState& s, double h, bool spin, double impact, std::size_t threads);
    std::uint64_t resolve_impacts(ParticleState& s, const Model& m, double h, double impact, std::size_t threads);
    void list_pair_particles();
    void index_pairs();
    // A struck particle's new path may leave the swept box the broad phase paired it by: the
    // particles that path may meet are paired with it then (path_reach.cpp).
    void reach_new_path(const ParticleState& s, std::uint32_t i, double h);
    void add_pair(const ParticleState& s, std::uint32_t i, std::uint32_t j, double h);
    bool paired(std::uint32_t i, std::uint32_t j) const;
    bool has_row(std::uint32_t i) const { return row_[i] < rows_ && pair_particles_[row_[i]] == i; }
    template <class Visit>
    void for_added_pairs_of(std::uint32_t i, Visit&& visit) const {
        for (std::uint32_t l = added_head_[i]; l != no_link; l = added_links_[l].next) visit(added_links_[l].pair);
    }
    void end_reach();  // after the impacts: pairs_ in order again, the step's lists cleared
    void queue_pairs_of(const std::vector<std::uint32_t>& resolved, std::uint32_t event);
    void queue_hits(std::size_t from);
    // Particle i takes dv (and dw) at time t of the step: its path bends there, and the solver's
    // start velocity (and spin) takes the change too, and its strike count one more. Returns the
    // change of its energy of motion.
    double strike(ParticleState& s, std::uint32_t i, double t, const Vec3& dv, const Vec3& dw, bool spin);
    void resolve(ParticleState& s, const Model& m, const Hit& hit, bool spin);
    // The walls among the impacts (wall_hits.cpp): the wall each particle just struck lies
    // against and moves into, appended to hits_, and one such hit resolved.
    void find_wall_hits(const ParticleState& s, const Model& m, double h, double impact);
    bool resolve_wall(ParticleState& s, const Model& m, const Hit& hit, double impact);  // false: no impulse
    // Moves particle i to x; the potential energy that gives it is the contacts' work.
    static void move_to(ParticleState& s, const Model& m, std::uint32_t i, const Vec3& x);
    // Moves particle i by `by`, kept inside the room; returns how far it went along `by`.
    static double shift_inside(ParticleState& s, const Model& m, const RoomBounds& room, std::uint32_t i, const Vec3& by);
    void remove_overlaps(ParticleState& s, const Model& m);  // overlap_removal.cpp
    void note_deep_overlap(const Pair& p, double contact, double distance);
    void keep_rest_on_walls(ParticleState& s, double impact);
    void touch(std::uint32_t i);

    // At the start of the step, per particle (the velocity and spin with the step's impacts added)
    std::vector<Vec3> start_, start_velocity_, start_spin_;
    // The current path of each particle touched this step: at path_time_ it is at path_start_ and
    // moves at path_rate_ (m/s) until the step's end.
    std::vector<Vec3> path_start_, path_rate_;
    std::vector<double> path_time_;
    // Per particle: the impacts it took this step (0 for the untouched); `corrected` in stamp_
    // once the overlap removal moved it (corrected_ lists those, to set back to 0).
    std::vector<std::uint32_t> strikes_, stamp_, corrected_;
    std::vector<std::uint32_t> caught_;  // the particles that reached max_strikes this step
    static constexpr std::uint32_t corrected = 0xffffffffu;
    std::vector<std::uint8_t> touched_;
    std::vector<std::uint8_t> listed_;  // per particle: 1 while list_pair_particles runs
    std::vector<std::uint32_t> moved_;
    SweptBoxes boxes_;
    bool ids_changed_ = false;  // boxes_.ids remade since the pair cache last saw them
    std::vector<double> task_reach_;          // per task of build_boxes
    std::vector<std::size_t> task_frozen_;
    PairCache pair_cache_;
    std::vector<Pair> pairs_;
    std::vector<Hit> hits_;
    // The impacts: the pairs to search (all, then those of the particles just struck), the
    // particles just struck, and each particle's pairs to find them (index_pairs).
    std::vector<std::uint32_t> queue_, resolved_, pair_start_, pair_fill_, pair_of_, pair_queued_;
    std::vector<std::uint32_t> row_;     // per particle: its row of pairs (valid for pair_particles_)
    std::uint32_t rows_ = 0;             // rows of index_pairs (the particles of the broad phase's pairs)
    std::size_t broad_pairs_ = 0;        // the broad phase's pairs, at index_pairs (the impacts add more)
    // The pairs the impacts added (reach_new_path): per particle the head of a list of its added
    // pairs, and the boxes that the paths of the particles whose paths left their swept boxes
    // covered this step (per particle 1 + its place in covers_, or 0).
    static constexpr std::uint32_t no_link = 0xffffffffu;
    struct AddedLink {
        std::uint32_t pair, next;
    };
    std::vector<std::uint32_t> added_head_, cover_of_, added_particles_, reached_, near_;
    std::vector<AddedLink> added_links_;
    std::vector<SweptBox> covers_;
    std::uint64_t added_total_ = 0;
    std::vector<std::uint32_t> pair_particles_;  // the particles of pairs_, each once (list_pair_particles)
    std::vector<std::vector<Hit>> slice_hits_;  // per slice of pairs, when threaded
    ContactSolver solver_;
    SleepIslands islands_;
    std::uint64_t resting_ = 0;
    std::vector<DeepOverlap> deep_overlaps_;
    std::vector<PairCrossing> crossings_;
    std::vector<std::pair<double, std::uint32_t>> bottom_up_;  // the overlap removal's order under shock
    std::vector<Event> wall_bounces_;
};

}  // namespace pl::collide
