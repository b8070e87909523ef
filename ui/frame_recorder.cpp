#include "ui/frame_recorder.hpp"

#include "physics/stepping/energy.hpp"
#include "physics/stepping/relaunch.hpp"
#include "ui/lab_ui.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pl::ui {
namespace {

// Starts recording a fresh experiment. The shell steps before it records, so the experiment is
// usually a frame past t = 0 already: the metrics and the first samples then start from the
// scene's initial state (what every fresh or reset experiment starts from), so nothing of the
// first frame is lost; the events of that frame are still pending and get observed next.
// Initial energies of the particles the ui can launch again (the tracked ones): a copy for every
// particle would cost 8 bytes each at millions.
std::vector<double> watched_energies(const Simulation& sim) {
    const auto& e = sim.state().initial_energy;
    return {e.begin(), e.begin() + static_cast<std::ptrdiff_t>(std::min(e.size(), PlotHistory::max_tracked_particles))};
}

void start_tracking(PlotHistory& h, const Experiment& e) {
    h.reset(e.variant_count(), e.variant_count() > 0 ? e.run(0).particle_count() : 0);
    h.source = &e;
    h.source_steps = e.base_steps();
    const bool metrics = h.particle_count <= PlotHistory::max_metrics_particles;
    std::vector<ParticleSpec> initial;
    if (metrics) initial = initial_particles(e.scene());
    const std::vector<ParticleSpec>& listed = metrics ? initial : e.scene().particles;
    if (!listed.empty()) h.launch_velocity = listed.front().velocity;
    for (std::size_t v = 0; v < e.variant_count(); ++v) {
        const Simulation& sim = e.run(v);
        VariantCursor& c = h.cursors[v];
        c.consumed_events = 0;
        c.dropped_events = sim.dropped_events();
        if (!metrics || initial.size() != sim.particle_count()) {
            c.observed_steps = sim.step_count();
            c.initial_energy = watched_energies(sim);
            continue;
        }
        const Simulation start(sim.model(), initial);  // the state at t = 0
        c.observed_steps = 0;
        c.initial_energy = watched_energies(start);
        h.trackers.push_back(start_metrics(start));
        std::vector<ParticleTrack>& tracks = h.variants[v].particles;
        const double floor_y = start.model().room.floor_y();
        for (std::size_t i = 0; i < tracks.size(); ++i) {
            const Vec3 vel = start.state().velocity(i);
            tracks[i].height.push(0.0, start.state().y[i] - floor_y);
            tracks[i].speed.push(0.0, glm::length(vel));
            tracks[i].kinetic.push(0.0, kinetic_energy(start.state().inertial_mass[i], vel));
            h.variants[v].paths[i].push(0.0, start.state().position(i));
        }
        const EnergyBreakdown total = total_energy(start.state(), start.model().world.gravity, start.model().room);
        LedgerTrack& l = h.variants[v].ledger;
        l.kinetic.push(0.0, total.kinetic);
        l.potential.push(0.0, total.potential);
        for (SampleSeries* zero : {&l.bounce, &l.friction, &l.drag, &l.wind_work}) zero->push(0.0, 0.0);
        l.residual.push(0.0, total.residual());
    }
    if (h.trackers.size() != e.variant_count()) h.trackers.clear();
}

// A particle launched again at time t from `position` with `velocity`: its metrics restart.
void restart_metrics(MetricsTracker& m, std::size_t i, const Vec3& position, const Vec3& velocity, double t) {
    if (i >= m.particles.size()) return;
    m.start_position[i] = position;
    m.prev[i] = {position, velocity};  // a replay of the step after it ends elsewhere: then not used
    m.particles[i] = ParticleMetrics{};
    m.particles[i].apex_height = position.y - m.floor_y;
    m.particles[i].apex_time = t;
    m.stopped_since[i].reset();
}

double event_height(const Room& room, const Event& e, double radius) {
    if (e.wall == Wall::y_min) return radius;
    if (e.wall == Wall::y_max) return room.size.y - radius;
    return std::numeric_limits<double>::quiet_NaN();  // a side wall: height unknown at that instant
}

// The exact state at an event makes bounces sharp in the plots (a V in the height, a jump in
// speed and kinetic energy) however coarsely the frames sample the flight.
void record_event_samples(ParticleTrack& track, const Room& room, const Event& e, double mass, double radius) {
    if (e.kind != EventKind::bounce && e.kind != EventKind::rest) return;
    const double h = event_height(room, e, radius);
    if (std::isfinite(h)) track.height.push(e.t, h);
    track.speed.push(e.t, e.speed_in);
    track.speed.push(e.t, e.speed_out);
    track.kinetic.push(e.t, 0.5 * mass * e.speed_in * e.speed_in);
    track.kinetic.push(e.t, 0.5 * mass * e.speed_out * e.speed_out);
}

// Everything that happened in the variant since the last observation: new events, a relaunch
// (the shell's L key changes a particle's initial energy), and one metrics observation.
void observe(LabSession& s, PlotHistory& h, std::size_t v, std::vector<LoggedEvent>& log) {
    Simulation& sim = s.experiment->run(v);
    VariantCursor& c = h.cursors[v];
    const ParticleState& state = sim.state();
    const std::vector<Event>& events = sim.events();
    // Events dropped by the simulation's own bound shift the indices.
    const std::uint64_t dropped = sim.dropped_events() - c.dropped_events;
    c.consumed_events = dropped >= c.consumed_events ? 0 : c.consumed_events - static_cast<std::size_t>(dropped);
    c.dropped_events = sim.dropped_events();
    if (c.consumed_events > events.size()) c.consumed_events = 0;  // drained by someone else
    if (sim.step_count() == c.observed_steps && c.consumed_events == events.size()) return;

    MetricsTracker* tracker = v < h.trackers.size() ? &h.trackers[v] : nullptr;
    // Only the tracked particles can be launched again from the ui (L key, inspector kick).
    const std::size_t watched = std::min({c.initial_energy.size(), state.size(), PlotHistory::max_tracked_particles});
    for (std::size_t i = 0; i < watched; ++i) {
        if (state.initial_energy[i] == c.initial_energy[i]) continue;
        c.initial_energy[i] = state.initial_energy[i];
        // Requests run before stepping, so the relaunch happened at the last observed time
        // from the preset's start position, with the launch velocity.
        if (!tracker) continue;
        const std::vector<ParticleSpec> start = initial_particles(s.scene);
        if (i < start.size()) restart_metrics(*tracker, i, start[i].position, s.launch_velocity, tracker->prev_time);
        if (i == 0) h.launch_velocity = s.launch_velocity;
    }

    const std::vector<Event> fresh(events.begin() + static_cast<std::ptrdiff_t>(c.consumed_events), events.end());
    c.consumed_events = events.size();
    const Room& room = sim.model().room;
    VariantTrack& track = h.variants[v];
    for (const Event& e : fresh) {
        log.push_back({static_cast<std::uint32_t>(v), e});
        if (e.particle < track.particles.size())
            record_event_samples(track.particles[e.particle], room, e, state.mass[e.particle], state.radius[e.particle]);
    }
    if (tracker && sim.step_count() != c.observed_steps) observe_step(*tracker, sim, fresh, 0.0);
    c.observed_steps = sim.step_count();
}

void observe_all(LabSession& s, PlotHistory& h) {
    std::vector<LoggedEvent> log;
    for (std::size_t v = 0; v < h.variants.size(); ++v) observe(s, h, v, log);
    // Variants are stepped one after the other: interleave their events in time.
    std::stable_sort(log.begin(), log.end(), [](const LoggedEvent& a, const LoggedEvent& b) { return a.event.t < b.event.t; });
    for (const LoggedEvent& e : log) h.log_event(e);
    h.source_steps = s.experiment->base_steps();
}

void sample_particles(PlotHistory& h, const Experiment& e, double t) {
    for (std::size_t v = 0; v < h.variants.size(); ++v) {
        const Simulation& sim = e.run(v);
        const ParticleState& st = sim.state();
        const double floor_y = sim.model().room.floor_y();
        VariantTrack& track = h.variants[v];
        for (std::size_t i = 0; i < track.particles.size() && i < st.size(); ++i) {
            const Vec3 vel = st.velocity(i);
            track.particles[i].height.push(t, st.y[i] - floor_y);
            track.particles[i].speed.push(t, glm::length(vel));
            track.particles[i].kinetic.push(t, kinetic_energy(st.inertial_mass[i], vel));
            track.paths[i].push(t, st.position(i));
        }
    }
    h.last_particle_sample = t;
}

void sample_aggregates(PlotHistory& h, const Experiment& e, double t) {
    for (std::size_t v = 0; v < h.variants.size(); ++v) {
        const Simulation& sim = e.run(v);
        const ParticleState& st = sim.state();
        const Model& m = sim.model();
        VariantTrack& track = h.variants[v];
        const EnergyBreakdown total = total_energy(st, m.world.gravity, m.room);
        LedgerTrack& l = track.ledger;
        l.kinetic.push(t, total.kinetic);
        l.potential.push(t, total.potential);
        l.bounce.push(t, total.dissipated_bounce);
        l.friction.push(t, total.dissipated_friction);
        l.drag.push(t, total.dissipated_drag);
        l.wind_work.push(t, total.wind_work);
        l.residual.push(t, total.residual());
        if (!h.aggregated() || st.size() == 0) continue;
        const double floor_y = m.room.floor_y();
        double sum_h = 0.0, lo = INFINITY, hi = -INFINITY;
        double sum_speed = 0.0, slowest = INFINITY, fastest = 0.0;
        for (std::size_t i = 0; i < st.size(); ++i) {
            const double height = st.y[i] - floor_y;
            sum_h += height;
            lo = std::min(lo, height);
            hi = std::max(hi, height);
            const double speed = std::sqrt(st.vx[i] * st.vx[i] + st.vy[i] * st.vy[i] + st.vz[i] * st.vz[i]);
            sum_speed += speed;
            slowest = std::min(slowest, speed);
            fastest = std::max(fastest, speed);
        }
        const double n = static_cast<double>(st.size());
        AggregateTrack& a = track.aggregate;
        a.height_mean.push(t, sum_h / n);
        a.height_min.push(t, lo);
        a.height_max.push(t, hi);
        a.speed_mean.push(t, sum_speed / n);
        a.speed_min.push(t, slowest);
        a.speed_max.push(t, fastest);
        a.kinetic_total.push(t, total.kinetic);
    }
}

}  // namespace

PlotHistory& history_of(LabSession& s) {
    if (!s.history) s.history = std::make_shared<PlotHistory>();
    PlotHistory& h = *s.history;
    if (s.experiment &&
        (h.source != s.experiment.get() || s.experiment->base_steps() < h.source_steps ||
         h.variants.size() != s.experiment->variant_count()))
        start_tracking(h, *s.experiment);
    return h;
}

namespace {

// Base steps from now until `interval_s` has passed since `last_t` (at least 1).
std::uint64_t steps_until(const Experiment& e, double last_t, double interval_s) {
    if (last_t < 0.0) return 1;
    const double due = last_t + interval_s * (1.0 - 1e-9) - e.time();
    return due <= 0.0 ? 1 : std::max<std::uint64_t>(1, static_cast<std::uint64_t>(std::ceil(due / e.base_dt())));
}

bool due(double last_t, double t, double interval_s) { return last_t < 0.0 || t - last_t >= interval_s * (1.0 - 1e-9); }

}  // namespace

std::uint64_t record_step(LabSession& s) {
    constexpr std::uint64_t no_limit = std::numeric_limits<std::uint64_t>::max();
    if (!s.experiment) return no_limit;
    PlotHistory& h = history_of(s);
    Experiment& e = *s.experiment;
    const double t = e.time();
    if (!h.trackers.empty()) observe_all(s, h);
    if (due(h.last_particle_sample, t, h.particle_interval_s())) sample_particles(h, e, t);
    if (due(h.last_time, t, h.aggregate_interval_s())) {
        sample_aggregates(h, e, t);
        h.last_time = t;
    }
    if (!h.trackers.empty()) return 1;  // live metrics observe every step
    return std::min(steps_until(e, h.last_particle_sample, h.particle_interval_s()),
                    steps_until(e, h.last_time, h.aggregate_interval_s()));
}

void record_frame(LabSession& s) {
    if (!s.experiment) return;
    PlotHistory& h = history_of(s);
    observe_all(s, h);
    // Samples come from record_step only (fixed simulated intervals); the frame hands the
    // recorded events back so the simulations' buffers stay small.
    Experiment& e = *s.experiment;
    for (std::size_t v = 0; v < e.variant_count(); ++v) {
        e.run(v).drain_events();
        h.cursors[v].consumed_events = 0;
    }
}

void kick_particle(LabSession& s, std::size_t i, const Vec3& velocity) {
    if (!s.experiment) return;
    PlotHistory& h = history_of(s);
    observe_all(s, h);
    const double t = s.experiment->time();
    for (std::size_t v = 0; v < s.experiment->variant_count(); ++v) {
        Simulation& sim = s.experiment->run(v);
        if (i >= sim.particle_count()) continue;
        const Vec3 position = sim.state().position(i);
        relaunch_particle(sim, i, position, velocity);
        if (i < h.cursors[v].initial_energy.size()) h.cursors[v].initial_energy[i] = sim.state().initial_energy[i];
        if (v < h.trackers.size()) restart_metrics(h.trackers[v], i, position, velocity, t);
    }
    if (i == 0) h.launch_velocity = velocity;
}

}  // namespace pl::ui
