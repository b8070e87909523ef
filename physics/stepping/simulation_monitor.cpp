// Simulation::monitor: the checks after a step (drag validity range, Mach number, stability of
// the explicit methods against the drag stiffness) and the Reynolds range observed over the scene.
// Two passes: a branch-free scan over the state arrays (vectorised, split over the threads like
// the kernel) finds the particles that need a warning; the warnings are then raised in particle
// order, so the result does not depend on the thread count.
#include "physics/stepping/simulation.hpp"

#include "physics/model/drag.hpp"
#include "physics/model/terms/term_list.hpp"
#include "physics/stepping/fast_kernel.hpp"
#include "physics/stepping/thread_pool.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

namespace pl {

namespace {

constexpr double mach_warning_speed = 0.3 * speed_of_sound_mps;  // m/s

struct MonitorLimits {
    ReRange valid;
    double dt, stability_limit;  // warn when dt * stiffness > stability_limit
};

// Identical: every particle has the drag constants of particle 0 (read once, not streamed).
// F: the scene's forces (with a drag term); its drag term's stiffness is inlined (vectorised for
// the linear and quadratic models).
template <class F, bool Identical>
void scan(const ParticleState& s, const WindField& wind, double t, const MonitorLimits& lim,
          const WarningBits* warned, std::size_t begin, std::size_t end, MonitorScan& out) {
    constexpr std::size_t chunk = 256;
    // 64-bit lanes (a byte-sized value would make GCC take 64 particles per vector iteration).
    std::int64_t skip[chunk], unwarned[chunk], suspect[chunk];
    double wx[chunk] = {}, wy[chunk] = {}, wz[chunk] = {};
    constexpr auto validity_bit = 1u << static_cast<unsigned>(WarningKind::drag_validity);
    constexpr auto mach_bit = 1u << static_cast<unsigned>(WarningKind::mach);
    constexpr auto stability_bit = 1u << static_cast<unsigned>(WarningKind::stability);
    constexpr auto above_bit = 1u << WarningSink::drag_above_range_bit;
    for (std::size_t c = begin; c < end; c += chunk) {
        const std::size_t n = std::min(end, c + chunk) - c;
        for (std::size_t j = 0; j < n; ++j) {
            skip[j] = (s.frozen[c + j] | s.resting[c + j]) != 0;
            // Kinds of warning the particle can still get (none while it rests or is frozen).
            unwarned[j] = skip[j] ? 0 : static_cast<WarningBits>(~warned[c + j]);
        }
        if constexpr (F::has_wind) {
            for (std::size_t j = 0; j < n; ++j) {
                const Vec3 w = wind.at(s.position(c + j), t);
                wx[j] = w.x;
                wy[j] = w.y;
                wz[j] = w.z;
            }
        }
        const double* const vx = s.vx.data() + c;
        const double* const vy = s.vy.data() + c;
        const double* const vz = s.vz.data() + c;
        const double* const drag_k = s.drag_k.data() + c;
        const double* const re_scale = s.drag_re_scale.data() + c;
        const double k0 = s.drag_k[0], re_scale0 = s.drag_re_scale[0];
        // Minima and maxima of doubles >= 0 as those of their bit patterns: the order is the
        // same, and an integer reduction vectorises where a floating-point one does not.
        std::int64_t max_k = std::bit_cast<std::int64_t>(out.max_stiffness);
        std::int64_t re_lo = std::bit_cast<std::int64_t>(out.reynolds.lo);
        std::int64_t re_hi = std::bit_cast<std::int64_t>(out.reynolds.hi);
        constexpr std::int64_t infinity_bits = std::bit_cast<std::int64_t>(std::numeric_limits<double>::infinity());
        for (std::size_t j = 0; j < n; ++j) {
            const double ux = vx[j] - wx[j], uy = vy[j] - wy[j], uz = vz[j] - wz[j];
            const double u = std::sqrt(ux * ux + uy * uy + uz * uz);
            const double scale = Identical ? re_scale0 : re_scale[j];
            const double re = scale * u;
            const bool moving = (skip[j] == 0) & (u > 0.0);
            const std::int64_t re_bits = std::bit_cast<std::int64_t>(re);
            // `moving` as a mask of all ones: GCC leaves a select here as a branch, which does not vectorise.
            const std::int64_t in = -static_cast<std::int64_t>(moving);
            const std::int64_t lo_bits = (re_bits & in) | (infinity_bits & ~in);
            const std::int64_t hi_bits = re_bits & in;
            re_lo = lo_bits < re_lo ? lo_bits : re_lo;
            re_hi = hi_bits > re_hi ? hi_bits : re_hi;
            const double k = F::DragTerm::stiffness(Identical ? k0 : drag_k[j], scale, u);
            const std::int64_t k_bits = skip[j] == 0 ? std::bit_cast<std::int64_t>(k) : 0;
            max_k = k_bits > max_k ? k_bits : max_k;
            // Only what the particle has not been warned about yet.
            const std::int64_t invalid = (u > 0.0) & (re < lim.valid.lo) ? validity_bit
                                         : (u > 0.0) & (re > lim.valid.hi) ? above_bit
                                                                           : 0;
            const std::int64_t fast = u > mach_warning_speed ? mach_bit : 0;
            const std::int64_t unstable = k * lim.dt > lim.stability_limit ? stability_bit : 0;
            suspect[j] = (invalid | fast | unstable) & unwarned[j];
        }
        out.max_stiffness = std::bit_cast<double>(max_k);
        out.reynolds = {std::bit_cast<double>(re_lo), std::bit_cast<double>(re_hi)};
        for (std::size_t j = 0; j < n; ++j)
            if (suspect[j]) out.suspects.push_back(static_cast<std::uint32_t>(c + j));
    }
}

using ScanFn = void (*)(const ParticleState&, const WindField&, double, const MonitorLimits&, const WarningBits*,
                        std::size_t, std::size_t, MonitorScan&);

// The scan for the terms the model enables (null without drag: nothing to watch).
ScanFn pick_scan(const Model& m, bool identical) {
    return terms::with_enabled_terms(m, [identical]<class F>() -> ScanFn {
        if constexpr (F::has_drag) return identical ? &scan<F, true> : &scan<F, false>;
        else return nullptr;
    });
}

}  // namespace

// The monitor only reads the state; beyond a handful of particles it samples every 32nd step
// (64 ms at the default 2 ms), so that it costs a few percent of the steps it watches: one scan
// costs about as much as a step (measured: every 8th step cost 10% at 1e3 particles). Warnings
// carry the time of the sample that saw them.
std::uint64_t Simulation::monitor_period() const { return state_.size() <= 64 ? 1 : 32; }

void Simulation::monitor() {
    if (model_.drag.model == DragModel::none) return;
    if (steps_ % monitor_period() != 0) return;
    const ReRange valid = drag_validity(model_.drag.model);
    const double limit = stability_limit(model_.integrator);
    const MonitorLimits lim{valid, dt(), limit};
    const ScanFn scan_range = pick_scan(model_, identical_particles_);
    const std::size_t n = state_.size();
    const std::size_t ranges = particle_ranges(n, threads_);
    scans_.resize(ranges);
    for (MonitorScan& s : scans_) {
        s.max_stiffness = 0.0;
        s.reynolds = {std::numeric_limits<double>::infinity(), 0.0};
        s.suspects.clear();
    }
    auto task = [&](std::size_t k) {
        scan_range(state_, wind_, time(), lim, warned_.data(), range_begin(n, ranges, k), range_begin(n, ranges, k + 1),
                   scans_[k]);
    };
    if (ranges == 1) task(0);
    else ThreadPool::shared().run(ranges, std::min(ranges, thread_count(threads_)), task);

    const WarningSink sink{&warnings_, &warned_};
    for (const MonitorScan& out : scans_) {
        max_stiffness_ = std::max(max_stiffness_, out.max_stiffness);
        reynolds_.lo = std::min(reynolds_.lo, out.reynolds.lo);
        reynolds_.hi = std::max(reynolds_.hi, out.reynolds.hi);
        for (const std::uint32_t i : out.suspects) {
            const double u = glm::length(air_velocity(i));
            const double re = state_.drag_re_scale[i] * u;
            if (u > 0.0 && (re < valid.lo || re > valid.hi))
                sink.raise(WarningKind::drag_validity, i, time(), re, re > valid.hi);
            if (u > mach_warning_speed) sink.raise(WarningKind::mach, i, time(), u);
            const double k = drag_stiffness(model_.drag.model, {state_.drag_k[i], state_.drag_re_scale[i]}, u);
            if (k * dt() > limit) sink.raise(WarningKind::stability, i, time(), k);
        }
    }
}

void Simulation::watch_rest(std::size_t first) {
    const WarningSink sink{&warnings_, &warned_};
    const double limit = no_rest_dt(model_);
    for (std::size_t k = first; k < events_.size(); ++k) {
        const Event& e = events_[k];
        if (e.kind == EventKind::bounce && e.wall >= 0 && (no_rest_floors_ & (1u << e.wall)))
            sink.raise(WarningKind::no_rest, e.particle, e.t, limit);
    }
}

}  // namespace pl
