// The fast kernel's per-range stepper (see fast_kernel.hpp): phase 1 (flight), the resting
// passes and phase 2 (contact lanes, generic fallback) for one contiguous range of particles, one
// or several steps per call. Part of the fast stepping kernel, included by fast_kernel.cpp alone
// (in an unnamed namespace, as it was inside that file: the same translation unit, so the same
// code is generated), which is compiled with -fno-trapping-math (CMakeLists.txt).
#pragma once

#include "physics/stepping/contact_lanes.hpp"
#include "physics/stepping/fast_kernel.hpp"
#include "physics/stepping/flight_chunk.hpp"
#include "physics/stepping/held_lanes.hpp"
#include "physics/stepping/lane_math.hpp"
#include "physics/stepping/particle_stepper.hpp"
#include "physics/stepping/slide_lane.hpp"

#include <algorithm>
#include <bit>
#include <cstring>
#include <vector>

namespace pl {

namespace {

using namespace fast;

// What one range of particles produced besides its state: kept apart per range and merged in
// range order, so the merged result does not depend on which thread ran which range. On cache
// lines of its own (two, for the adjacent-line prefetcher): its event vector grows while
// another thread fills the next range's.
struct alignas(128) RangeOutput {
    std::vector<Event>* events = nullptr;  // the simulation's sink when there is one range
    std::vector<Event> own_events;
    std::vector<Warning> frozen;  // the warnings of the particles frozen during this step, in order
    ForceCounters counters;
};

// From this many resting or frozen particles in a chunk, the resting ones slide in place (a
// vector pass over the whole chunk) rather than through the contact lanes. Measured on a room at
// rest (workload drag_rest): about 15 ns per resting particle through the lanes, about 3.5 ns per
// particle of the chunk for the pass; they break even near 60 of 256.
constexpr std::size_t slide_in_place_from = 64;

template <Flight M, class F>
class RangeStepper {
public:

    // outs: one per step of the call, in step order.
    RangeStepper(const KernelContext& k, RangeOutput* outs, std::uint32_t steps)
        : k_(k), s_(k.state), m_(k.model), room_(m_.room), outs_(outs), out_(outs), steps_(steps),
          first_step_(k.step), rho_(m_.world.air.density_kg_m3),
          adaptive_on_(m_.integrator.method == Method::dopri5 && m_.integrator.adaptive),
          identical_(k.identical_particles), from_memory_(k.state.size() > cache_resident_particles),
          ctx_{&room_, &m_.contact, m_.integrator.method, m_.integrator.rtol, m_.integrator.atol, outs->events,
               adaptive_on_ ? &adaptive_ : nullptr, &contact_solves_},
          stepper_(ctx_, f_), t0_(k.time()), h_(m_.integrator.dt) {
        f_.load(scene_inputs(m_, &k.wind));
        if constexpr (M != Flight::none) {
            // Force evaluations of one fixed step and of one call (a step may look the wind up).
            F step = f_, call = f_;
            fixed_step<M>(FlightState{}, t0_, h_, step);
            call(Vec3(0.0), Vec3(0.0), t0_);
            per_step_ = step.evaluations();
            per_call_ = call.evaluations();
        }
    }

    // All steps of the call for particles [begin, end). Several steps go block by block: each
    // block of particles takes every step while it is in cache (particles are independent, and
    // each step's events are kept apart, so the results are those of one step at a time).
    void run(std::size_t begin, std::size_t end) {
        const std::size_t block = steps_ == 1 ? end - begin : block_length(end - begin);
        for (std::size_t b = begin; b < end; b += block) {
            for (std::uint32_t k = 0; k < steps_; ++k) {
                start_step(k);
                run_step(b, std::min(end, b + block));
            }
        }
        // Phase 1 evaluated the forces of every particle it finished once per method stage.
        f_.add_evaluations(per_step_, fast_);
        ForceCounters& c = outs_[0].counters;
        add_counts(c, f_, adaptive_, contact_solves_);
        c.fast_path += fast_;
    }

private:
    // Step k of the call: its time, and where its events and frozen particles go.
    void start_step(std::uint32_t k) {
        t0_ = static_cast<double>(first_step_ + k) * h_;  // Simulation::time() at that step
        out_ = &outs_[k];
        ctx_.events = out_->events;
        // Only the first step of a block streams the state from memory; the others find it in cache.
        streaming_ = from_memory_ && k == 0;
    }

    // One step of particles [begin, end).
    void run_step(std::size_t begin, std::size_t end) {
        if constexpr (M == Flight::none) {
            for (std::size_t i = begin; i < end; ++i) step_generic(i);
        } else {
            // Phase 2 waits until a batch of flagged particles has gathered (from several chunks
            // in a sparse scene), in particle order. Particles are independent and only phase 2
            // makes events, so the results and the order of the events are the same. (A software
            // prefetch of the ledger lines phase 2 writes cost more than it saved: 5% at 1e6.)
            HeldLanes held;
            LaneBits flagged[chunk_groups];
            for (std::size_t c = begin; c < end; c += fast_chunk) {
                const std::size_t c_end = std::min(end, c + fast_chunk), n = c_end - c;
                held.mark(s_, c, c_end);
                if (held.count() == n && all_held_still(c, c_end, held.lanes())) {
                    count_evals(per_call_, n);  // the generic slide evaluates the forces once
                    continue;
                }
                std::size_t finished = 0;
                if (held.count() < n) {
                    finished = flight(c, c_end, held, flagged);
                } else {
                    std::copy_n(held.bits(), (n + lane_group - 1) / lane_group, flagged);  // all held: no phase 1
                }
                // The slide of a resting particle does not depend on the method (ParticleStepper::
                // slide), so every fixed-step method takes it.
                const std::size_t slid =
                    held.count() >= slide_in_place_from ? slide_chunk(c, c_end, held.lanes(), flagged) : 0;
                fast_ += finished;
                if (finished + slid == n) continue;
                for_each_flagged(c, c_end, flagged, [this](std::size_t i) {
                    pending_[pending_count_++] = static_cast<std::uint32_t>(i);
                });
                if (pending_count_ >= contact_batch) contact_phase();
            }
            if (pending_count_ > 0) contact_phase();
        }
    }

    // Calls f(particle) for the flagged particles of a chunk, in order.
    template <class Fn>
    static void for_each_flagged(std::size_t c, std::size_t c_end, const LaneBits* flagged, const Fn& f) {
        for (std::size_t g = 0; g < c_end - c; g += lane_group)
            for (LaneBits w = flagged[g / lane_group]; w != 0; w &= w - 1)
                f(c + g + static_cast<std::size_t>(std::countr_zero(w)));
    }

    // Particles resting on one wall slide in place, in a vector loop over the chunk, when enough
    // of the chunk rests (a room whose balls have come to rest): what slide_lanes does for a batch
    // of gathered particles, without the gather, the scatter and a store_step per particle, which
    // had made a particle-step on the floor ten times as dear as one in flight. Clears the flags
    // of the particles it finished and returns how many.
    std::size_t slide_chunk(std::size_t c, std::size_t c_end, const LaneMask* held, LaneBits* flagged) {
        return identical_ ? slide_chunk<true>(c, c_end, held, flagged) : slide_chunk<false>(c, c_end, held, flagged);
    }
    // Identical: as for flight_chunk (a load from a per-particle or a shared address does not vectorise).
    template <bool Identical>
    [[gnu::flatten, gnu::noinline]] std::size_t slide_chunk(std::size_t c, std::size_t c_end, const LaneMask* held,
                                                            LaneBits* flagged) {
        const double gx = f_.gravity.x, gy = f_.gravity.y, gz = f_.gravity.z;
        const WindField* const wind = f_.wind_field();
        const double rho = rho_;
        const RoomBounds room = room_;
        const double friction = m_.contact.friction;
        const double t0 = t0_, h = h_;
        double* const px = s_.x.data();
        double* const py = s_.y.data();
        double* const pz = s_.z.data();
        double* const vx = s_.vx.data();
        double* const vy = s_.vy.data();
        double* const vz = s_.vz.data();
        double* const drag_loss = s_.dissipated_drag.data();
        double* const wind_work = s_.wind_work.data();
        double* const friction_loss = s_.dissipated_friction.data();
        const double* const mass = s_.mass.data();
        const double* const radius = s_.radius.data();
        const double* const drag_k = s_.drag_k.data();
        const double* const re_scale = s_.drag_re_scale.data();
        const double mass0 = mass[0], radius0 = radius[0], k0 = drag_k[0], re_scale0 = re_scale[0];
        // Particle i's slide, if it rests on one wall and the slide keeps it there; whether it did.
        const auto slide = [&](std::size_t i) [[gnu::always_inline]] {
            const LaneMask code = held[i - c];
            // One resting wall (one bit of the low byte) and not frozen (nothing above it).
            const bool one_wall = (code != 0) & ((code & (code - 1)) == 0) & (code < 0x100);
            const double m = Identical ? mass0 : mass[i];
            const double r = Identical ? radius0 : radius[i];
            F f;
            f.load({.gx = gx, .gy = gy, .gz = gz, .wind = wind, .k = Identical ? k0 : drag_k[i],
                    .re_scale = Identical ? re_scale0 : re_scale[i], .mass = m, .radius = r, .air_density = rho});
            const Slide q = slide_lane(f, room, friction, t0, h, r, code, px[i], py[i], pz[i], vx[i], vy[i], vz[i]);
            const bool take = one_wall & q.ok;
            px[i] = take ? q.x : px[i];
            py[i] = take ? q.y : py[i];
            pz[i] = take ? q.z : pz[i];
            vx[i] = take ? q.vx : vx[i];
            vy[i] = take ? q.vy : vy[i];
            vz[i] = take ? q.vz : vz[i];
            // store_step's ledger increments (its bounce increment, mass * 0, changes nothing).
            friction_loss[i] = take ? friction_loss[i] + m * q.friction_loss : friction_loss[i];
            if constexpr (F::writes_drag) drag_loss[i] = take ? drag_loss[i] + m * q.drag_loss : drag_loss[i];
            if constexpr (F::writes_air_work) wind_work[i] = take ? wind_work[i] + m * q.wind_gain : wind_work[i];
            return take;
        };
        // The slid particles' flags cleared group by group (bit_of: see flight_chunk).
        std::size_t slid = 0;
        for (std::size_t g = c; g < c_end; g += lane_group) {
            const std::size_t len = std::min(lane_group, c_end - g);
            LaneBits slid_bits = 0;
#pragma GCC ivdep
            for (std::size_t j = 0; j < len; ++j) slid_bits |= bit_if(slide(g + j), j);
            flagged[(g - c) / lane_group] &= ~slid_bits;
            slid += static_cast<std::size_t>(std::popcount(slid_bits));
        }
        count_evals(per_call_, slid);  // the forces at the step start, once per slide
        return slid;
    }

    // The resting-wall bits of the walls on which a particle at rest stays exactly as it is:
    // without wind the forces on a particle with v = +0 are gravity alone (the drag of u = 0 is
    // 0 for every finite drag constant), so the slide's outcome is the same for every particle
    // and is found once, by running it. Where it is "still, ok, v = +0, x unchanged", the slide
    // changes no bit of the particle (its ledger increments are mass * +0) and is skipped.
    std::int64_t walls_that_hold_still() const {
        if constexpr (!F::rest_is_uniform) {
            return 0;
        } else {
            if (s_.size() == 0) return 0;
            F f;
            f.load({.gx = f_.gravity.x, .gy = f_.gravity.y, .gz = f_.gravity.z, .k = s_.drag_k[0],
                    .re_scale = s_.drag_re_scale[0]});
            const Vec3 x = 0.5 * (room_.lo + room_.hi);
            std::int64_t walls = 0;
            for (std::int64_t bit = 1; bit < 64; bit <<= 1) {
                const Slide q = slide_lane(f, room_, m_.contact.friction, t0_, h_, 0.0, bit, x.x, x.y, x.z, 0.0, 0.0, 0.0);
                const bool unchanged = (std::bit_cast<std::uint64_t>(q.vx) | std::bit_cast<std::uint64_t>(q.vy) |
                                        std::bit_cast<std::uint64_t>(q.vz)) == 0 &&
                                       q.x == x.x && q.y == x.y && q.z == x.z;
                if (q.ok && unchanged) walls |= bit;
            }
            return walls;
        }
    }

    // Whether every particle of a chunk rests on one wall of still_walls_ with v = +0 exactly
    // (and is not frozen), so that its step changes nothing. still_walls_ is found on the first
    // call (six scalar slides: as much as a step of a few hundred particles in flight).
    bool all_held_still(std::size_t c, std::size_t c_end, const LaneMask* held) {
        if (still_walls_ < 0) still_walls_ = walls_that_hold_still();
        if (still_walls_ == 0) return false;
        const double* const vx = s_.vx.data();
        const double* const vy = s_.vy.data();
        const double* const vz = s_.vz.data();
        const std::int64_t walls = still_walls_;
        std::uint64_t moving = 0;
        for (std::size_t i = c; i < c_end; ++i) {
            const LaneMask code = held[i - c];
            const bool one_still_wall = (code != 0) & ((code & (code - 1)) == 0) & ((code & ~walls) == 0);
            moving |= (std::bit_cast<std::uint64_t>(vx[i]) | std::bit_cast<std::uint64_t>(vy[i]) |
                       std::bit_cast<std::uint64_t>(vz[i])) |
                      static_cast<std::uint64_t>(!one_still_wall);
        }
        return moving == 0;
    }

    // Phase 1 of a chunk; its loop takes whole vectors when the state streams from memory.
    std::size_t flight(std::size_t c, std::size_t c_end, const HeldLanes& held, LaneBits* flags) {
        const LaneBits* const bits = held.bits();
        if (streaming_)
            return identical_ ? flight_chunk<M, F, true, true>(s_, c, c_end, f_, room_, t0_, h_, rho_, bits, flags)
                              : flight_chunk<M, F, false, true>(s_, c, c_end, f_, room_, t0_, h_, rho_, bits, flags);
        return identical_ ? flight_chunk<M, F, true, false>(s_, c, c_end, f_, room_, t0_, h_, rho_, bits, flags)
                          : flight_chunk<M, F, false, false>(s_, c, c_end, f_, room_, t0_, h_, rho_, bits, flags);
    }

    // Phase 2 for the pending particles, in order: for methods whose position is a polynomial in
    // the step, free particles go through bounce_lanes and particles resting on one wall through
    // slide_lanes; the ones these cannot finish, and every other flagged particle, through the
    // generic stepper.
    void contact_phase() {
        const std::size_t n = pending_count_;
        pending_count_ = 0;
        if constexpr (has_polynomial_position(method_of(M))) {
            // Which lanes each pending particle goes to: 0 bounce, 1 slide, 2 scalar.
            std::uint8_t route[contact_batch + fast_chunk];
            BounceLanes lanes;
            SlideLanes sliding;
            std::size_t k = 0, m = 0;
            for (std::size_t q = 0; q < n; ++q) {
                const std::uint32_t i = pending_[q];
                const std::uint8_t walls = s_.resting[i];
                route[q] = s_.frozen[i] ? 2 : walls == 0 ? 0 : std::has_single_bit(walls) ? 1 : 2;
                const std::size_t p = identical_ ? 0 : i;
                if (route[q] == 0) {
                    gather(lanes, k++, s_, i, p);
                } else if (route[q] == 1) {
                    sliding.wall_bit[m] = walls;
                    gather(sliding, m++, s_, i, p);
                }
            }
            bounce_lanes<M>(lanes, k, f_, room_, m_.contact, t0_, h_, rho_);
            slide_lanes(sliding, m, f_, room_, m_.contact.friction, t0_, h_, rho_);
            std::size_t j = 0, l = 0;
            for (std::size_t q = 0; q < n; ++q) {
                const std::uint32_t i = pending_[q];
                if (route[q] == 0 && lanes.ok[j++]) commit_bounce(lanes, j - 1, i);
                else if (route[q] == 1 && sliding.ok[l++]) commit_slide(sliding, l - 1, i);
                else step_generic(i);
            }
            apply_deferred();
        } else {
            for (std::size_t q = 0; q < n; ++q) step_generic(pending_[q]);
        }
    }

    // Writes lane j's slide back to particle i (it keeps resting on its wall).
    void commit_slide(const SlideLanes& L, std::size_t j, std::uint32_t i) {
        count_evals(per_call_, 1);
        ParticleStep p;
        p.y.x = Vec3(L.x[j], L.y[j], L.z[j]);
        p.y.v = Vec3(L.vx[j], L.vy[j], L.vz[j]);
        p.y.drag_loss = L.drag_loss[j];
        p.y.wind_gain = L.wind_gain[j];
        p.resting = s_.resting[i];
        p.friction_loss = L.friction_loss[j];
        commit(i, p);
    }

    // Writes lane j's bounce back to particle i, as ParticleStepper::advance would have.
    void commit_bounce(const BounceLanes& L, std::size_t j, std::uint32_t i) {
        count_evals(per_step_, static_cast<std::uint64_t>(L.flights[j]));
        count_evals(per_call_, 2);  // the forces at the step start (time of impact) and after the impact
        ++contact_solves_;
        if (L.notify[j])
            out_->events->push_back(
                {L.t[j], i, static_cast<std::int8_t>(L.wall[j]), EventKind::bounce, L.speed_in[j], L.speed_out[j]});
        ParticleStep p;
        p.y.x = Vec3(L.x[j], L.y[j], L.z[j]);
        p.y.v = Vec3(L.vx[j], L.vy[j], L.vz[j]);
        p.y.drag_loss = L.drag_loss[j];
        p.y.wind_gain = L.wind_gain[j];
        p.resting = 0;
        p.bounce_loss = L.bounce_loss[j];
        p.friction_loss = L.friction_loss[j];
        commit(i, p);
    }

    // store_step for a lane's particle, with the bounce and friction ledger additions kept back
    // for apply_deferred: the flight never touches those two arrays, so at 1e6 particles each
    // commit missed twice in the cache and the TLB, in between the lanes' work. Added together
    // after the batch's commits, the misses overlap (+3-8% at 1e6 one step per call in
    // alternating rounds; taking the two additions out altogether gave +11%). Same bits: a
    // particle is committed once per step, and the batch's additions are applied before its next.
    void commit(std::uint32_t i, const ParticleStep& p) {
        const double mass = s_.mass[identical_ ? 0 : i];
        store_motion<F>(s_, i, p, nullptr, mass);
        deferred_[deferred_count_++] = {i, mass * p.bounce_loss, mass * p.friction_loss};
    }

    // The ledger additions commit() kept back, in commit order.
    void apply_deferred() {
        double* const bounce = s_.dissipated_bounce.data();
        double* const friction = s_.dissipated_friction.data();
        for (std::size_t q = 0; q < deferred_count_; ++q) {
            const Deferred& d = deferred_[q];
            bounce[d.i] += d.bounce;
            friction[d.i] += d.friction;
        }
        deferred_count_ = 0;
    }

    // Adds `times` evaluations of the kind `per` counts to the functor's counters, as if the
    // lanes had evaluated the forces through it.
    void count_evals(const ForceCounters& per, std::uint64_t times) { f_.add_evaluations(per, times); }

    // The generic kernel's per-particle body (simulation.cpp, step_kernel), operation for operation.
    void step_generic(std::size_t i) {
        if (s_.frozen[i]) return;
        const auto id = static_cast<std::uint32_t>(i);
        const std::size_t q = identical_ ? 0 : i;
        TermInputs in = scene_inputs(m_, &k_.wind);
        in.k = s_.drag_k[q];
        in.re_scale = s_.drag_re_scale[q];
        in.mass = s_.mass[q];
        in.radius = s_.radius[q];
        f_.load(in);
        std::vector<double>* hints = adaptive_on_ ? &k_.adaptive_hint : nullptr;
        ParticleStep p = load_step(s_, i, hints, s_.radius[q]);
        const bool finished = stepper_.advance(p, id, t0_, h_);
        if (const StepFault fault = step_fault(p.y, finished); fault != StepFault::none) {
            out_->frozen.push_back(freeze_particle(s_, id, t0_, fault, p.y, *out_->events));
            return;
        }
        store_step<F>(s_, i, p, hints, s_.mass[q]);
    }

    const KernelContext& k_;
    ParticleState& s_;
    const Model& m_;
    const RoomBounds room_;
    RangeOutput* const outs_;
    RangeOutput* out_;  // the current step's
    const std::uint32_t steps_;
    const std::uint64_t first_step_;
    const double rho_;  // air density (body terms of the air load it per particle)
    std::size_t fast_ = 0;  // particle-steps phase 1 finished
    const bool adaptive_on_;
    const bool identical_;
    const bool from_memory_;
    bool streaming_ = false;
    std::uint32_t pending_[contact_batch + fast_chunk];  // flagged particles waiting for phase 2
    std::size_t pending_count_ = 0;
    struct Deferred {
        std::uint32_t i;
        double bounce, friction;  // mass * per-kg loss, as store_step adds them
    };
    Deferred deferred_[contact_batch + fast_chunk];  // see commit()
    std::size_t deferred_count_ = 0;
    ForceCounters per_step_, per_call_;                  // force evaluations in one step, one call
    std::int64_t still_walls_ = -1;                      // see walls_that_hold_still; -1: not yet
    AdaptiveStats adaptive_;
    std::uint64_t contact_solves_ = 0;
    F f_;
    StepContext ctx_;  // its event sink follows the step (the stepper holds a reference)
    const ParticleStepper<F> stepper_;
    double t0_;
    const double h_;
};

}  // namespace

}  // namespace pl
