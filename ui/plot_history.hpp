// What the ui records about the running experiment, with bounded memory: plot series, the
// event log and the live comparison metrics. No ImGui and no physics stepping: the frame
// recorder (ui/frame_recorder.cpp) fills it, the plots and tables read it, the unit tests drive
// it alone.
#pragma once

#include "physics/model/scene.hpp"
#include "physics/stepping/events.hpp"
#include "physics/studies/metrics.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <tuple>
#include <utility>
#include <vector>

namespace pl::ui {

// One time series (t, v) in at most `capacity` samples. When full, the older half is reduced
// 2:1 by keeping the lowest and the highest sample of every four (in time order), so recent
// data stays at full resolution, older data thins out geometrically, and no peak or trough is
// ever lost. Times are stored contiguously so the plot can draw straight from them.
class SampleSeries {
public:
    static constexpr std::size_t min_capacity = 16;

    SampleSeries() : SampleSeries(8192) {}
    explicit SampleSeries(std::size_t capacity) { set_capacity(capacity); }

    // Rounded up to a multiple of 8 (the compaction works on groups of four in half the buffer).
    void set_capacity(std::size_t capacity) {
        capacity_ = std::max(min_capacity, (capacity + 7) / 8 * 8);
        while (t_.size() >= capacity_) compact();
        t_.reserve(capacity_);
        v_.reserve(capacity_);
    }

    // Appends a sample; one that is earlier than the last one is ignored (times ascend).
    void push(double t, double v) {
        if (!t_.empty() && t < t_.back()) return;
        if (t_.size() == capacity_) compact();
        t_.push_back(t);
        v_.push_back(v);
    }

    void clear() {
        t_.clear();
        v_.clear();
    }

    std::size_t size() const { return t_.size(); }
    bool empty() const { return t_.empty(); }
    std::size_t capacity() const { return capacity_; }
    const double* times() const { return t_.data(); }
    const double* values() const { return v_.data(); }
    double last_time() const { return t_.empty() ? 0.0 : t_.back(); }
    double last_value() const { return v_.empty() ? 0.0 : v_.back(); }

private:
    void compact() {
        const std::size_t half = capacity_ / 2;  // multiple of 4
        std::size_t out = 0;
        for (std::size_t group = 0; group < half; group += 4) {
            std::size_t lo = group, hi = group;
            for (std::size_t i = group + 1; i < group + 4; ++i) {
                if (v_[i] < v_[lo]) lo = i;
                if (v_[i] > v_[hi]) hi = i;
            }
            // A flat group (or one of NaNs) keeps its two ends instead.
            if (lo == hi) {
                lo = group;
                hi = group + 3;
            }
            for (std::size_t keep : {std::min(lo, hi), std::max(lo, hi)}) {
                t_[out] = t_[keep];
                v_[out] = v_[keep];
                ++out;
            }
        }
        for (std::size_t i = half; i < t_.size(); ++i, ++out) {
            t_[out] = t_[i];
            v_[out] = v_[i];
        }
        t_.resize(out);
        v_.resize(out);
    }

    std::size_t capacity_ = 0;
    std::vector<double> t_, v_;
};

// Positions of one particle at a fixed simulated interval (a pinned run's ghost path in the 3D
// view). When full, every other sample goes and the interval doubles, so the samples stay evenly
// spaced in time however long the run. A particle at rest adds nothing (same position).
class PathSeries {
public:
    static constexpr std::size_t capacity = 4096;
    static constexpr double initial_interval_s = 1.0 / 200.0;

    // Records `p` at time t once an interval has passed since the last recorded sample.
    void push(double t, const Vec3& p) {
        if (!t_.empty() && (t - t_.back() < interval_s_ * (1.0 - 1e-9) || p == p_.back())) return;
        if (t_.size() == capacity) thin();
        t_.push_back(t);
        p_.push_back(p);
    }
    std::size_t size() const { return t_.size(); }
    double time(std::size_t k) const { return t_[k]; }
    const Vec3& position(std::size_t k) const { return p_[k]; }
    double interval_s() const { return interval_s_; }

private:
    void thin() {
        std::size_t out = 0;
        for (std::size_t k = 0; k < t_.size(); k += 2, ++out) {
            t_[out] = t_[k];
            p_[out] = p_[k];
        }
        t_.resize(out);
        p_.resize(out);
        interval_s_ *= 2.0;
    }

    double interval_s_ = initial_interval_s;
    std::vector<double> t_;
    std::vector<Vec3> p_;
};

// Each track's `all()` lists its series, so that the sample budget counts and sizes exactly these.

// What the plots show for one particle of one variant.
struct ParticleTrack {
    SampleSeries height, speed, kinetic;
    auto all() { return std::array{&height, &speed, &kinetic}; }
};

// With many particles the plots show aggregates instead of one line each.
struct AggregateTrack {
    SampleSeries height_mean, height_min, height_max, speed_mean, speed_min, speed_max, kinetic_total;
    auto all() {
        return std::array{&height_mean, &height_min, &height_max, &speed_mean, &speed_min, &speed_max, &kinetic_total};
    }
};

// Energy ledger of a whole variant (sums over its particles), J.
struct LedgerTrack {
    SampleSeries kinetic, potential, bounce, friction, drag, wind_work, residual;
    auto all() { return std::array{&kinetic, &potential, &bounce, &friction, &drag, &wind_work, &residual}; }
};

// How many series a track of type T has.
template <class T>
constexpr std::size_t series_count = std::tuple_size_v<decltype(std::declval<T&>().all())>;

struct VariantTrack {
    std::vector<ParticleTrack> particles;  // the first PlotHistory::max_tracked_particles
    std::vector<PathSeries> paths;         // their positions
    AggregateTrack aggregate;              // every particle
    LedgerTrack ledger;
};

struct LoggedEvent {
    std::uint32_t variant = 0;
    Event event;
};

// Bookkeeping of the recorder for one variant.
struct VariantCursor {
    std::uint64_t observed_steps = 0;   // Simulation::step_count() at the last observation
    std::size_t consumed_events = 0;    // events()[0, consumed) are already recorded
    std::uint64_t dropped_events = 0;   // Simulation::dropped_events() at the last observation
    std::vector<double> initial_energy; // per tracked particle: a change means it was launched again
};

struct PlotHistory {
    static constexpr std::size_t max_tracked_particles = 16;
    static constexpr std::size_t max_logged_events = 20000;
    // Total samples over all series (16 bytes each): about 64 MB at most, however long the run.
    static constexpr std::size_t sample_budget = 4'000'000;
    static constexpr std::size_t max_series_capacity = 131072;

    // Live metrics (time of flight, apex, ...) need every step observed, O(particles) each:
    // beyond this many particles the comparison is left to the timed run.
    static constexpr std::size_t max_metrics_particles = 1000;

    std::vector<VariantTrack> variants;
    std::deque<LoggedEvent> events;   // newest last, at most max_logged_events
    std::uint64_t events_dropped = 0; // older events pushed out of `events`
    std::size_t particle_count = 0;   // particles per variant in the experiment
    double last_time = -1.0;          // simulated time of the last ledger / aggregate sample
    double last_particle_sample = -1.0;  // simulated time of the last per-particle sample
    Vec3 launch_velocity{0.0};        // particle 0's velocity at its latest launch (a pinned run's setting)

    const void* source = nullptr;     // the Experiment recorded (a new one starts over)
    std::uint64_t source_steps = 0;   // its base steps at the last observation (fewer: a reset)
    std::vector<VariantCursor> cursors;
    std::vector<MetricsTracker> trackers;  // empty beyond max_metrics_particles

    // Sizes the tracks for `variant_count` variants of `particle_count` particles, spreading the
    // sample budget over every series.
    void reset(std::size_t variant_count, std::size_t particle_count_) {
        particle_count = particle_count_;
        const std::size_t tracked = std::min(particle_count, max_tracked_particles);
        const std::size_t series_per_variant =
            series_count<ParticleTrack> * tracked + series_count<AggregateTrack> + series_count<LedgerTrack>;
        const std::size_t series = std::max<std::size_t>(1, variant_count * series_per_variant);
        const std::size_t capacity = std::clamp(sample_budget / series, std::size_t{1024}, max_series_capacity);
        variants.assign(variant_count, VariantTrack{});
        for (VariantTrack& v : variants) {
            v.particles.resize(tracked);
            v.paths.resize(tracked);
            for (ParticleTrack& p : v.particles)
                for (SampleSeries* s : p.all()) s->set_capacity(capacity);
            for (SampleSeries* s : v.aggregate.all()) s->set_capacity(capacity);
            for (SampleSeries* s : v.ledger.all()) s->set_capacity(capacity);
        }
        events.clear();
        events_dropped = 0;
        last_time = -1.0;
        last_particle_sample = -1.0;
        cursors.assign(variant_count, VariantCursor{});
        trackers.clear();
        source = nullptr;
        source_steps = 0;
    }

    void log_event(const LoggedEvent& e) {
        if (events.size() == max_logged_events) {
            events.pop_front();
            ++events_dropped;
        }
        events.push_back(e);
    }

    bool aggregated() const { return particle_count > max_tracked_particles; }

    // Simulated seconds between two samples of the ledger and the aggregates (O(particles) each),
    // and between two samples of the tracked particles. Fixed intervals, never frames: a jump
    // ahead ("Next event") is sampled like a smooth run.
    double aggregate_interval_s() const { return particle_count <= max_metrics_particles ? 0.005 : 0.02; }
    double particle_interval_s() const { return aggregated() ? aggregate_interval_s() : 5e-4; }
};

}  // namespace pl::ui
