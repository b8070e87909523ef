#include "fast_kernel.hpp"

#include "particle_stepper.hpp"
#include "thread_pool.hpp"

#include <algorithm>
#include <bit>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <type_traits>

namespace pl {

namespace {

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

// False if any of them is Inf or NaN, as a plain compare that vectorises (std::isfinite does
// not). Finite values whose sum overflows also give false: the particle then merely takes the
// generic path, which decides exactly as it always does.
inline bool all_finite(double a, double b, double c, double d, double e) {
    return std::abs(a) + std::abs(b) + std::abs(c) + std::abs(d) + std::abs(e) <= DBL_MAX;
}

// What one range of particles produced besides its state: kept apart per range and merged in
// range order, so the merged result does not depend on which thread ran which range. On cache
// lines of its own (two, for the adjacent-line prefetcher): its event vector grows while
// another thread fills the next range's.
struct alignas(128) RangeOutput {
    std::vector<Event>* events = nullptr;  // the simulation's sink when there is one range
    std::vector<Event> own_events;
    std::vector<std::uint32_t> frozen;  // particles frozen during this step, in order
    ForceCounters counters;
};

// Methods whose one force evaluation per step is at the step start: for them phase 1 looks the
// wind up for the whole chunk first (WindField::at is an opaque call), then runs the vector loop.
template <Flight M, bool HasWind>
constexpr bool wind_ahead = HasWind && (M == Flight::explicit_euler || M == Flight::semi_implicit_euler);

// Forces<Drag, true> for a particle whose wind w is already known: Forces::operator() computes
// u = v - w, then everything from u, so still air evaluated at u gives the same bits (u - 0 is
// u); the wind's work is dot(-c u, w) as there. fast_kernel_test checks the bits.
template <DragModel Drag>
struct KnownWindForces {
    Forces<Drag, false> still_air;
    Vec3 w{0.0};
    Derivative operator()(const Vec3& x, const Vec3& v, double t) const {
        const Vec3 u = v - w;
        Derivative d = still_air(x, u, t);
        d.wind_power = glm::dot(-still_air.drag_rate(u) * u, w);
        return d;
    }
};

// The force functor phase 1 uses for one particle, filled in place from scalars: GCC keeps it
// in registers only if no glm vector or whole functor is copied (the copy of a union-based
// glm::dvec3 blocks scalarisation, and with it vectorisation).
template <Flight M, DragModel Drag, bool HasWind>
using FlightForces = std::conditional_t<wind_ahead<M, HasWind>, KnownWindForces<Drag>, Forces<Drag, HasWind>>;

template <DragModel Drag, bool HasWind>
void set_forces(Forces<Drag, HasWind>& f, double gx, double gy, double gz, const WindField* wind, double k,
                double re_scale, double, double, double) {
    f.gravity.x = gx;
    f.gravity.y = gy;
    f.gravity.z = gz;
    if constexpr (HasWind) f.wind = wind;
    f.drag = {k, re_scale};
}

template <DragModel Drag>
void set_forces(KnownWindForces<Drag>& f, double gx, double gy, double gz, const WindField*, double k,
                double re_scale, double wx, double wy, double wz) {
    set_forces(f.still_air, gx, gy, gz, nullptr, k, re_scale, 0.0, 0.0, 0.0);
    f.w.x = wx;
    f.w.y = wy;
    f.w.z = wz;
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
    const Vec3 end = x + h * v_new;
    const bool end_inside = clear_of_walls(room, end, r);
    const Vec3 moved = clamp_inside(room, end, r);
    const Vec3 x_new(when(still, x.x, moved.x), when(still, x.y, moved.y), when(still, x.z, moved.z));
    const bool finite = all_finite(x_new.x, x_new.y, x_new.z, v_new.x, v_new.y) &
                        all_finite(v_new.z, drag_loss, wind_gain, friction_loss, 0.0);
    return {x_new.x, x_new.y, x_new.z, v_new.x, v_new.y, v_new.z, drag_loss, wind_gain, friction_loss,
            static_cast<bool>(!released & !(was_moving & still) & (still | end_inside) & finite)};
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

// Lane masks of phase 1 are 64-bit: a byte-sized value in the vectorised loop would make GCC
// take 64 particles per iteration (one vector of bytes), spilling the 8-wide double vectors.
using LaneMask = std::int64_t;

// The particles of a chunk that phase 1 must leave alone (resting or frozen), as 64-bit lanes
// holding resting | frozen << 8 (zero for a free particle). They stay all zeros between chunks:
// only groups of 64 particles where a flag byte is set (found by ORing the bytes eight at a
// time, a reduction that vectorises) are widened, and cleared when the next chunk is marked.
// In flight most groups have none, and widening every byte cost more than the look.
class HeldLanes {
public:
    static constexpr std::size_t group = 64;

    const LaneMask* mark(const ParticleState& s, std::size_t begin, std::size_t end) {
        const std::uint8_t* const resting = s.resting.data() + begin;
        const std::uint8_t* const frozen = s.frozen.data() + begin;
        const std::size_t n = end - begin;
        clear();
        count_ = 0;
        for (std::size_t g = 0; g < n; g += group) {
            const std::size_t len = std::min(group, n - g);
            if (!any_set(resting + g, frozen + g, len)) continue;
            std::size_t held = 0;
            for (std::size_t j = g; j < g + len; ++j) {
                lanes_[j] = resting[j] | LaneMask{frozen[j]} << 8;
                held += lanes_[j] != 0;
            }
            count_ += held;
            widened_ |= std::uint32_t{1} << (g / group);
        }
        return lanes_;
    }

    // How many particles of the chunk last marked are held.
    std::size_t count() const { return count_; }

private:
    // Zeros the groups the last chunk widened.
    void clear() {
        for (; widened_ != 0; widened_ &= widened_ - 1)
            std::fill_n(lanes_ + std::countr_zero(widened_) * group, group, LaneMask{0});
    }

    static bool any_set(const std::uint8_t* a, const std::uint8_t* b, std::size_t n) {
        std::uint64_t any = 0;
        std::size_t i = 0;
        for (; i + 8 <= n; i += 8) {
            std::uint64_t wa, wb;
            std::memcpy(&wa, a + i, sizeof wa);
            std::memcpy(&wb, b + i, sizeof wb);
            any |= wa | wb;
        }
        for (; i < n; ++i) any |= static_cast<std::uint64_t>(a[i] | b[i]);
        return any != 0;
    }

    alignas(64) LaneMask lanes_[fast_chunk] = {};
    std::uint32_t widened_ = 0;  // groups holding a non-zero mask
    std::size_t count_ = 0;
};
static_assert(fast_chunk / HeldLanes::group <= 32);

// Phase 1 for particles [begin, end): see fast_kernel.hpp. Writes flagged[i - begin] and
// returns the number of particles it finished. Identical: every particle has the mass, radius
// and drag constants of particle 0, so they are read once instead of streamed per particle.
// WholeVectors: the state is written back in whole vectors (old values where a particle is
// left for phase 2) instead of masked stores. Measured on the development machine (AVX-512,
// bench/RESULTS.md): masked stores are faster while the state is in cache, whole vectors when it
// streams from memory (about +10% at 1e6 particles, -13% at 1e4). Out of line: inlined into the
// range loop, its speed moved by up to 20% with unrelated changes to the code around it.
template <Flight M, DragModel Drag, bool HasWind, bool Identical, bool WholeVectors>
[[gnu::flatten, gnu::noinline]] std::size_t flight_chunk(ParticleState& s, std::size_t begin, std::size_t end,
                                                         const Forces<Drag, HasWind>& forces, const RoomBounds& room,
                                                         double t0, double h, const LaneMask* blocked,
                                                         LaneMask* flagged) {
    // Local copies the stores below provably cannot alias.
    const double gx = forces.gravity.x, gy = forces.gravity.y, gz = forces.gravity.z;
    const double lo_x = room.lo.x, lo_y = room.lo.y, lo_z = room.lo.z;
    const double hi_x = room.hi.x, hi_y = room.hi.y, hi_z = room.hi.z;
    const WindField* const wind = forces.wind;
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
    if constexpr (wind_ahead<M, HasWind>) {
        for (std::size_t i = begin; i < end; ++i) {
            const Vec3 w = wind->at(Vec3(px[i], py[i], pz[i]), t0);
            wx[i - begin] = w.x;
            wy[i - begin] = w.y;
            wz[i - begin] = w.z;
        }
    }
    std::size_t finished = 0;
#pragma GCC ivdep
    for (std::size_t i = begin; i < end; ++i) {
        double w[3] = {0.0, 0.0, 0.0};
        if constexpr (wind_ahead<M, HasWind>) {
            w[0] = wx[i - begin];
            w[1] = wy[i - begin];
            w[2] = wz[i - begin];
        }
        const double m = Identical ? mass0 : mass[i];
        const double r = Identical ? radius0 : radius[i];
        FlightForces<M, Drag, HasWind> f;
        set_forces(f, gx, gy, gz, wind, Identical ? k0 : drag_k[i], Identical ? re_scale0 : re_scale[i], w[0], w[1],
                   w[2]);
        FlightState y0;
        y0.x = Vec3(px[i], py[i], pz[i]);
        y0.v = Vec3(vx[i], vy[i], vz[i]);
        const FlightState y1 = fixed_step<M>(y0, t0, h, f);
        // The generic stepper's "no wall reached" test, RoomBounds::distance(w, x, r) >= 0 for
        // every wall, as x >= lo + r and x <= hi - r: the sign of a difference is exact, so the
        // same decision. It also implies a finite position, so only the rest is checked below.
        const bool inside = (y1.x.x >= lo_x + r) & (y1.x.x <= hi_x - r) & (y1.x.y >= lo_y + r) &
                            (y1.x.y <= hi_y - r) & (y1.x.z >= lo_z + r) & (y1.x.z <= hi_z - r);
        // Semi-implicit Euler moves by h * v1 (h > 0): an infinite or NaN v1 makes the position
        // infinite or NaN, so `inside` already implies a finite velocity; the ledger is left.
        const bool finite = M == Flight::semi_implicit_euler
                                ? std::abs(y1.drag_loss) + std::abs(y1.wind_gain) <= DBL_MAX
                                : all_finite(y1.v.x, y1.v.y, y1.v.z, y1.drag_loss, y1.wind_gain);
        const bool take = inside & finite & (blocked[i - begin] == 0);
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
        if constexpr (Drag != DragModel::none) {
            drag_loss[i] = take ? drag_loss[i] + m * y1.drag_loss : drag_loss[i];
            if constexpr (HasWind) wind_work[i] = take ? wind_work[i] + m * y1.wind_gain : wind_work[i];
        }
        flagged[i - begin] = !take;
        finished += take;
    }
    return finished;
}

// Flagged particles gathered before phase 2 runs (a full batch fills the vector lanes of the
// contact kernel several times over; it stays small enough for the data to be in cache).
constexpr std::size_t contact_batch = 64;
// From this many resting or frozen particles in a chunk, the resting ones slide in place (a
// vector pass over the whole chunk) rather than through the contact lanes. Measured on a room at
// rest (workload drag_rest): about 15 ns per resting particle through the lanes, about 3.5 ns per
// particle of the chunk for the pass; they break even near 60 of 256.
constexpr std::size_t slide_in_place_from = 64;

template <Flight M, DragModel Drag, bool HasWind>
class RangeStepper {
public:
    using F = Forces<Drag, HasWind>;

    // outs: one per step of the call, in step order.
    RangeStepper(Simulation& sim, RangeOutput* outs, std::uint32_t steps)
        : sim_(sim), s_(sim.mutable_state()), m_(sim.model()), room_(m_.room), outs_(outs), out_(outs),
          steps_(steps), first_step_(sim.step_count()),
          adaptive_on_(m_.integrator.method == Method::dopri5 && m_.integrator.adaptive),
          identical_(sim.identical_particles()),
          from_memory_(sim.particle_count() > cache_resident_particles),
          ctx_{&room_, &m_.contact, m_.integrator.method, m_.integrator.rtol, m_.integrator.atol, outs->events,
               adaptive_on_ ? &adaptive_ : nullptr, &contact_solves_},
          stepper_(ctx_, f_), t0_(sim.time()), h_(m_.integrator.dt) {
        f_.gravity = m_.world.gravity;
        f_.wind = &sim.wind();
        if constexpr (M != Flight::none) {
            // Force evaluations of one fixed step and of one call (a step may look the wind up).
            F step = f_, call = f_;
            fixed_step<M>(FlightState{}, t0_, h_, step);
            call(Vec3(0.0), Vec3(0.0), t0_);
            per_step_ = {step.gravity_evals, step.drag_evals, step.wind_evals};
            per_call_ = {call.gravity_evals, call.drag_evals, call.wind_evals};
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
        ForceCounters& c = outs_[0].counters;
        add_counts(c, f_, adaptive_, contact_solves_);
        c.fast_path += fast_;
        // Phase 1 evaluated the forces of every particle it finished once per method stage.
        c.gravity += fast_ * per_step_.gravity;
        c.drag += fast_ * per_step_.drag;
        c.wind += fast_ * per_step_.wind;
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
            LaneMask flagged[fast_chunk];
            for (std::size_t c = begin; c < end; c += fast_chunk) {
                const std::size_t c_end = std::min(end, c + fast_chunk), n = c_end - c;
                const LaneMask* const held_lanes = held.mark(s_, c, c_end);
                if (held.count() == n && all_held_still(c, c_end, held_lanes)) {
                    count_evals(per_call_, n);  // the generic slide evaluates the forces once
                    continue;
                }
                std::size_t finished = 0;
                if (held.count() < n) {
                    finished = flight(c, c_end, held_lanes, flagged);
                } else {
                    std::fill_n(flagged, n, LaneMask{1});  // all held: nothing for phase 1
                }
                // The slide of a resting particle does not depend on the method (ParticleStepper::
                // slide), so every fixed-step method takes it.
                const std::size_t slid =
                    held.count() >= slide_in_place_from ? slide_chunk(c, c_end, held_lanes, flagged) : 0;
                fast_ += finished;
                if (finished + slid == n) continue;
                for_each_flagged(c, c_end, n - finished - slid, flagged, [this](std::size_t i) {
                    pending_[pending_count_++] = static_cast<std::uint32_t>(i);
                });
                if (pending_count_ >= contact_batch) contact_phase();
            }
            if (pending_count_ > 0) contact_phase();
        }
    }

    // Calls f(particle) for the `count` flagged particles of a chunk, in order. A chunk usually
    // has one or two, and a look at every flag cost about a tenth of the flight itself, so
    // groups of 64 flags are ORed together first (a reduction that vectorises), a group with a
    // flag is narrowed to bytes and read eight bytes per word, and the look stops at the last.
    template <class Fn>
    static void for_each_flagged(std::size_t c, std::size_t c_end, std::size_t count, const LaneMask* flagged,
                                 const Fn& f) {
        constexpr std::size_t group = 64;
        const std::size_t n = c_end - c;
        for (std::size_t g = 0; g < n && count > 0; g += group) {
            const std::size_t len = std::min(group, n - g);
            LaneMask any = 0;
            for (std::size_t j = 0; j < len; ++j) any |= flagged[g + j];
            if (any == 0) continue;
            alignas(64) std::uint8_t bytes[group] = {};
            for (std::size_t j = 0; j < len; ++j) bytes[j] = static_cast<std::uint8_t>(flagged[g + j]);
            for (std::size_t k = 0; k < len; k += 8) {
                std::uint64_t word;
                std::memcpy(&word, bytes + k, sizeof word);
                for (; word != 0; word &= word - 1, --count)
                    f(c + g + k + static_cast<std::size_t>(std::countr_zero(word)) / 8);
            }
        }
    }

    // Particles resting on one wall slide in place, in a vector loop over the chunk, when enough
    // of the chunk rests (a room whose balls have come to rest): what slide_lanes does for a batch
    // of gathered particles, without the gather, the scatter and a store_step per particle, which
    // had made a particle-step on the floor ten times as dear as one in flight. Clears the flags
    // of the particles it finished and returns how many.
    std::size_t slide_chunk(std::size_t c, std::size_t c_end, const LaneMask* held, LaneMask* flagged) {
        return identical_ ? slide_chunk<true>(c, c_end, held, flagged) : slide_chunk<false>(c, c_end, held, flagged);
    }
    // Identical: as for flight_chunk (a load from a per-particle or a shared address does not vectorise).
    template <bool Identical>
    [[gnu::flatten, gnu::noinline]] std::size_t slide_chunk(std::size_t c, std::size_t c_end, const LaneMask* held,
                                                            LaneMask* flagged) {
        const double gx = f_.gravity.x, gy = f_.gravity.y, gz = f_.gravity.z;
        const WindField* const wind = f_.wind;
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
        std::size_t slid = 0;
#pragma GCC ivdep
        for (std::size_t i = c; i < c_end; ++i) {
            const LaneMask code = held[i - c];
            // One resting wall (one bit of the low byte) and not frozen (nothing above it).
            const bool one_wall = (code != 0) & ((code & (code - 1)) == 0) & (code < 0x100);
            F f;
            set_forces(f, gx, gy, gz, wind, Identical ? k0 : drag_k[i], Identical ? re_scale0 : re_scale[i], 0.0, 0.0,
                       0.0);
            const Slide q = slide_lane(f, room, friction, t0, h, Identical ? radius0 : radius[i], code, px[i], py[i],
                                       pz[i], vx[i], vy[i], vz[i]);
            const bool take = one_wall & q.ok;
            const double m = Identical ? mass0 : mass[i];
            px[i] = take ? q.x : px[i];
            py[i] = take ? q.y : py[i];
            pz[i] = take ? q.z : pz[i];
            vx[i] = take ? q.vx : vx[i];
            vy[i] = take ? q.vy : vy[i];
            vz[i] = take ? q.vz : vz[i];
            // store_step's ledger increments (its bounce increment, mass * 0, changes nothing).
            friction_loss[i] = take ? friction_loss[i] + m * q.friction_loss : friction_loss[i];
            if constexpr (Drag != DragModel::none) {
                drag_loss[i] = take ? drag_loss[i] + m * q.drag_loss : drag_loss[i];
                if constexpr (HasWind) wind_work[i] = take ? wind_work[i] + m * q.wind_gain : wind_work[i];
            }
            flagged[i - c] = take ? 0 : flagged[i - c];
            slid += take;
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
        if constexpr (HasWind || Drag == DragModel::sphere_re) {
            return 0;
        } else {
            if (s_.size() == 0) return 0;
            F f;
            set_forces(f, f_.gravity.x, f_.gravity.y, f_.gravity.z, nullptr, s_.drag_k[0], s_.drag_re_scale[0], 0.0,
                       0.0, 0.0);
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

    std::size_t flight(std::size_t c, std::size_t c_end, const LaneMask* blocked, LaneMask* flags) {
        if (identical_) {
            return streaming_ ? flight_chunk<M, Drag, HasWind, true, true>(s_, c, c_end, f_, room_, t0_, h_, blocked, flags)
                                : flight_chunk<M, Drag, HasWind, true, false>(s_, c, c_end, f_, room_, t0_, h_, blocked, flags);
        }
        return streaming_ ? flight_chunk<M, Drag, HasWind, false, true>(s_, c, c_end, f_, room_, t0_, h_, blocked, flags)
                            : flight_chunk<M, Drag, HasWind, false, false>(s_, c, c_end, f_, room_, t0_, h_, blocked, flags);
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
                    gather(lanes, k++, i, p);
                } else if (route[q] == 1) {
                    sliding.wall_bit[m] = walls;
                    gather(sliding, m++, i, p);
                }
            }
            bounce_lanes(lanes, k);
            slide_lanes(sliding, m);
            std::size_t j = 0, l = 0;
            for (std::size_t q = 0; q < n; ++q) {
                const std::uint32_t i = pending_[q];
                if (route[q] == 0 && lanes.ok[j++]) commit_bounce(lanes, j - 1, i);
                else if (route[q] == 1 && sliding.ok[l++]) commit_slide(sliding, l - 1, i);
                else step_generic(i);
            }
        } else {
            for (std::size_t q = 0; q < n; ++q) step_generic(pending_[q]);
        }
    }

    // Particle i's state into lane j; p is whose mass, radius and drag constants it has.
    template <class Lanes>
    void gather(Lanes& L, std::size_t j, std::uint32_t i, std::size_t p) const {
        L.x[j] = s_.x[i];
        L.y[j] = s_.y[i];
        L.z[j] = s_.z[i];
        L.vx[j] = s_.vx[i];
        L.vy[j] = s_.vy[i];
        L.vz[j] = s_.vz[i];
        L.k[j] = s_.drag_k[p];
        L.re_scale[j] = s_.drag_re_scale[p];
        L.r[j] = s_.radius[p];
    }

    // Flagged free particles of one batch, and what bounce_lanes made of them.
    struct BounceLanes {
        static constexpr std::size_t capacity = contact_batch + fast_chunk;
        double x[capacity], y[capacity], z[capacity], vx[capacity], vy[capacity], vz[capacity];
        double k[capacity], re_scale[capacity], r[capacity];
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
    [[gnu::flatten, gnu::noinline]] void bounce_lanes(BounceLanes& L, std::size_t n) const {
        constexpr double kappa = position_kappa(method_of(M));
        const double gx = f_.gravity.x, gy = f_.gravity.y, gz = f_.gravity.z;
        const WindField* const wind = f_.wind;
        const double lo_x = room_.lo.x, lo_y = room_.lo.y, lo_z = room_.lo.z;
        const double hi_x = room_.hi.x, hi_y = room_.hi.y, hi_z = room_.hi.z;
        const RoomBounds room = room_;
        const ContactSettings contact = m_.contact;
        const double t0 = t0_, h = h_;
#pragma GCC ivdep
        for (std::size_t j = 0; j < n; ++j) {
            F f;
            set_forces(f, gx, gy, gz, wind, L.k[j], L.re_scale[j], 0.0, 0.0, 0.0);
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
            const Vec3 a0 = f(y0.x, y0.v, t0).a;
            // Selections by wall and axis as bit masks (exact, and they vectorise where a chain
            // of conditionals does not).
            const std::uint64_t w0 = wall == 0 ? ~std::uint64_t{0} : 0, w1 = wall == 1 ? ~std::uint64_t{0} : 0;
            const std::uint64_t w2 = wall == 2 ? ~std::uint64_t{0} : 0, w3 = wall == 3 ? ~std::uint64_t{0} : 0;
            const std::uint64_t w4 = wall == 4 ? ~std::uint64_t{0} : 0, w5 = wall == 5 ? ~std::uint64_t{0} : 0;
            const std::uint64_t ax = w0 | w1, ay = w2 | w3, az = w4 | w5;
            const double d0 = select6(w0, y0.x.x - (lo_x + r), w1, (hi_x - r) - y0.x.x, w2, y0.x.y - (lo_y + r), w3,
                                      (hi_y - r) - y0.x.y, w4, y0.x.z - (lo_z + r), w5, (hi_z - r) - y0.x.z);
            const double sign = is_max ? -1.0 : 1.0;
            const double v_axis = select3(ax, y0.v.x, ay, y0.v.y, az, y0.v.z);
            const double a_axis = select3(ax, a0.x, ay, a0.y, az, a0.z);
            const double s_hit = first_contact_root(d0, sign * v_axis, sign * kappa * a_axis, h);
            const FlightState part = fixed_step<M>(y0, t0, s_hit, f);
            const bool moved = s_hit > 0.0;
            FlightState y;
            y.x = Vec3(when(moved, part.x.x, y0.x.x), when(moved, part.x.y, y0.x.y), when(moved, part.x.z, y0.x.z));
            y.v = Vec3(when(moved, part.v.x, y0.v.x), when(moved, part.v.y, y0.v.y), when(moved, part.v.z, y0.v.z));
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
            const bool slow = hit.normal_speed_out < contact.rest_speed;
            y.v = hit.v_out;
            const double speed_out = glm::length(y.v);
            const FlightState y_end = fixed_step<M>(y, t, remaining, f);
            const bool end_inside = clear_of_walls(room, y_end.x, r);
            const bool go_on = remaining > 0.0;
            const double ox = when(go_on, y_end.x.x, y.x.x), oy = when(go_on, y_end.x.y, y.x.y);
            const double oz = when(go_on, y_end.x.z, y.x.z), ovx = when(go_on, y_end.v.x, y.v.x);
            const double ovy = when(go_on, y_end.v.y, y.v.y), ovz = when(go_on, y_end.v.z, y.v.z);
            const double loss = when(go_on, y_end.drag_loss, y.drag_loss);
            const double gain = when(go_on, y_end.wind_gain, y.wind_gain);
            // Conservative: a finite state whose sum overflows goes to the generic path too.
            const bool finite = all_finite(ox, oy, oz, ovx, ovy) & all_finite(ovz, loss, gain, 0.0, 0.0);
            L.ok[j] = (crossed == 1) & !slow & (!go_on | end_inside) & finite;
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
            L.flights[j] = 1 + moved + go_on;
        }
    }

    // Particles resting on one wall, and what slide_lanes made of them.
    struct SlideLanes {
        static constexpr std::size_t capacity = contact_batch + fast_chunk;
        double x[capacity], y[capacity], z[capacity], vx[capacity], vy[capacity], vz[capacity];
        double k[capacity], re_scale[capacity], r[capacity];
        double drag_loss[capacity], wind_gain[capacity], friction_loss[capacity];
        std::int64_t wall_bit[capacity], ok[capacity];
    };

    // slide_lane for lanes [0, n).
    [[gnu::flatten, gnu::noinline]] void slide_lanes(SlideLanes& L, std::size_t n) const {
        const double gx = f_.gravity.x, gy = f_.gravity.y, gz = f_.gravity.z;
        const WindField* const wind = f_.wind;
        const RoomBounds room = room_;
        const double friction = m_.contact.friction;
        const double t0 = t0_, h = h_;
#pragma GCC ivdep
        for (std::size_t j = 0; j < n; ++j) {
            F f;
            set_forces(f, gx, gy, gz, wind, L.k[j], L.re_scale[j], 0.0, 0.0, 0.0);
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
        store_step<Drag, HasWind>(s_, i, p, nullptr, s_.mass[identical_ ? 0 : i]);
    }

    // Writes lane j's bounce back to particle i, as ParticleStepper::advance would have.
    void commit_bounce(const BounceLanes& L, std::size_t j, std::uint32_t i) {
        count_evals(per_step_, static_cast<std::uint64_t>(L.flights[j]));
        count_evals(per_call_, 1);  // the acceleration at the step start, for the time of impact
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
        store_step<Drag, HasWind>(s_, i, p, nullptr, s_.mass[identical_ ? 0 : i]);
    }

    // Adds `times` evaluations of the kind `per` counts to the functor's counters, as if the
    // lanes had evaluated the forces through it.
    void count_evals(const ForceCounters& per, std::uint64_t times) {
        f_.gravity_evals += times * per.gravity;
        f_.drag_evals += times * per.drag;
        f_.wind_evals += times * per.wind;
    }

    // The generic kernel's per-particle body (simulation.cpp, step_kernel), operation for operation.
    void step_generic(std::size_t i) {
        if (s_.frozen[i]) return;
        const auto id = static_cast<std::uint32_t>(i);
        const std::size_t q = identical_ ? 0 : i;
        f_.drag = {s_.drag_k[q], s_.drag_re_scale[q]};
        std::vector<double>* hints = adaptive_on_ ? &sim_.adaptive_step_hint() : nullptr;
        ParticleStep p = load_step(s_, i, hints, s_.radius[q]);
        stepper_.advance(p, id, t0_, h_);
        if (!is_finite(p.y)) {
            s_.frozen[i] = 1;
            out_->events->push_back({t0_, id, -1, EventKind::frozen, glm::length(s_.velocity(i)), 0.0});
            out_->frozen.push_back(id);
            return;
        }
        store_step<Drag, HasWind>(s_, i, p, hints, s_.mass[q]);
    }

    Simulation& sim_;
    ParticleState& s_;
    const Model& m_;
    const RoomBounds room_;
    RangeOutput* const outs_;
    RangeOutput* out_;  // the current step's
    const std::uint32_t steps_;
    const std::uint64_t first_step_;
    std::size_t fast_ = 0;  // particle-steps phase 1 finished
    const bool adaptive_on_;
    const bool identical_;
    const bool from_memory_;
    bool streaming_ = false;
    std::uint32_t pending_[contact_batch + fast_chunk];  // flagged particles waiting for phase 2
    std::size_t pending_count_ = 0;
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

// Adds a range's counters and warnings to the simulation (events are already in place).
void merge(Simulation& sim, const RangeOutput& out) {
    ForceCounters& c = sim.mutable_counters();
    c.gravity += out.counters.gravity;
    c.drag += out.counters.drag;
    c.wind += out.counters.wind;
    c.accepted_steps += out.counters.accepted_steps;
    c.rejected_steps += out.counters.rejected_steps;
    c.contacts += out.counters.contacts;
    c.fast_path += out.counters.fast_path;
    for (const std::uint32_t i : out.frozen) sim.raise(WarningKind::frozen, i);
}

template <Flight M, DragModel Drag, bool HasWind>
void fast_step_kernel(Simulation& sim, std::uint32_t steps) {
    const std::size_t n = sim.particle_count();
    const std::size_t ranges = particle_ranges(n, sim.threads());
    if (ranges <= 1 && steps == 1) {
        RangeOutput out;
        out.events = &sim.event_sink();
        RangeStepper<M, Drag, HasWind>(sim, &out, 1).run(0, n);
        merge(sim, out);
        sim.finish_step();
        return;
    }
    // One output per range and step (range k's steps at k * steps). Kept from call to call (one
    // set per calling thread), so that the event vectors keep their room instead of being
    // allocated, grown and freed every call. The tasks reach it through `outs`: named inside a
    // task, `kept` would be the worker's own, empty copy.
    static thread_local std::vector<RangeOutput> kept;
    std::vector<RangeOutput>& outs = kept;
    outs.resize(ranges * steps);
    for (RangeOutput& out : outs) {
        out.events = &out.own_events;
        out.own_events.clear();
        out.frozen.clear();
        out.counters = {};
    }
    auto task = [&](std::size_t k) {
        RangeStepper<M, Drag, HasWind>(sim, &outs[k * steps], steps)
            .run(range_begin(n, ranges, k), range_begin(n, ranges, k + 1));
    };
    if (ranges == 1) task(0);
    else ThreadPool::shared().run(ranges, std::min(ranges, thread_count(sim.threads())), task);
    // Step by step, range by range: the order one step at a time gives.
    std::vector<Event>& sink = sim.event_sink();
    for (std::uint32_t step = 0; step < steps; ++step) {
        for (std::size_t k = 0; k < ranges; ++k) {
            const RangeOutput& out = outs[k * steps + step];
            sink.insert(sink.end(), out.own_events.begin(), out.own_events.end());
            merge(sim, out);
        }
        sim.finish_step();
    }
}

template <Flight M>
StepKernel pick_forces(const Model& m) {
    // Wind acts only through drag: without drag the wind field is never consulted.
    const bool wind = m.world.wind.kind != WindKind::none && m.drag.model != DragModel::none;
    switch (m.drag.model) {
        case DragModel::none: return &fast_step_kernel<M, DragModel::none, false>;
        case DragModel::linear:
            return wind ? &fast_step_kernel<M, DragModel::linear, true> : &fast_step_kernel<M, DragModel::linear, false>;
        case DragModel::quadratic:
            return wind ? &fast_step_kernel<M, DragModel::quadratic, true>
                        : &fast_step_kernel<M, DragModel::quadratic, false>;
        case DragModel::sphere_re:
            return wind ? &fast_step_kernel<M, DragModel::sphere_re, true>
                        : &fast_step_kernel<M, DragModel::sphere_re, false>;
    }
    return &fast_step_kernel<M, DragModel::none, false>;
}

}  // namespace

bool has_fast_flight(const Model& m) {
    switch (m.integrator.method) {
        case Method::explicit_euler:
        case Method::semi_implicit_euler:
        case Method::velocity_verlet:
        case Method::rk4: return true;
        case Method::dopri5:
        case Method::exponential: return false;
    }
    return false;
}

StepKernel pick_fast_kernel(const Model& m) {
    switch (m.integrator.method) {
        case Method::explicit_euler: return pick_forces<Flight::explicit_euler>(m);
        case Method::semi_implicit_euler: return pick_forces<Flight::semi_implicit_euler>(m);
        case Method::velocity_verlet: return pick_forces<Flight::velocity_verlet>(m);
        case Method::rk4: return pick_forces<Flight::rk4>(m);
        case Method::dopri5:
        case Method::exponential: return pick_forces<Flight::none>(m);
    }
    return pick_forces<Flight::none>(m);
}

std::size_t block_length(std::size_t n) {
    const std::size_t blocks = std::max<std::size_t>(1, (n + block_particles / 2) / block_particles);
    return (n / blocks + fast_chunk - 1) / fast_chunk * fast_chunk;
}

// Boundaries on multiples of 64 particles keep the threads' stores off each other's cache lines.
std::size_t range_begin(std::size_t n, std::size_t ranges, std::size_t k) {
    if (k >= ranges) return n;
    return (n * k / ranges) & ~std::size_t{63};
}

std::size_t thread_count(int threads) { return static_cast<std::size_t>(threads > 0 ? threads : hardware_threads()); }

std::size_t particle_ranges(std::size_t n, int threads) {
    const std::size_t t = thread_count(threads);
    if (t <= 1) return 1;
    return std::max<std::size_t>(1, std::min(t * ranges_per_thread, n / min_particles_per_range));
}

}  // namespace pl
