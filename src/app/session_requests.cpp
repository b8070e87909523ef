#include "app/session_requests.hpp"

#include "physics/stepping/relaunch.hpp"

#include <fmt/format.h>

#include <chrono>
#include <vector>

namespace pl::app {

namespace {

constexpr double next_event_horizon_s = 10.0;     // simulated time searched for the next event
constexpr double next_event_wall_budget_s = 2.0;  // real time the search may take

bool is_notable(EventKind k) { return k != EventKind::lift; }

// Steps until some variant records a bounce, rest, stop or freeze; then pauses there.
void run_to_next_event(ui::LabSession& s, const AfterSteps& after_step) {
    Experiment& e = *s.experiment;
    std::vector<std::size_t> seen(e.variant_count());
    for (std::size_t v = 0; v < e.variant_count(); ++v) seen[v] = e.run(v).events().size();
    const double t_end = e.time() + next_event_horizon_s;
    const auto start = std::chrono::steady_clock::now();
    s.paused = true;
    while (e.time() < t_end) {
        e.step_base(1);
        if (after_step) after_step();
        for (std::size_t v = 0; v < e.variant_count(); ++v) {
            const std::vector<Event>& events = e.run(v).events();
            for (std::size_t k = seen[v]; k < events.size(); ++k) {
                if (!is_notable(events[k].kind)) continue;
                const Event& ev = events[k];
                const std::string& label = e.run(v).model().label;
                s.status_message = fmt::format("Stopped at t = {:.4f} s: {} of particle {}{}", e.time(),
                                               to_string(ev.kind), ev.particle, label.empty() ? "" : " (" + label + ")");
                return;
            }
            seen[v] = events.size();
        }
        if (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > next_event_wall_budget_s) {
            s.status_message = fmt::format("No event by t = {:.3f} s (search stopped after {:.0f} s of real time)",
                                           e.time(), next_event_wall_budget_s);
            return;
        }
    }
    s.status_message = fmt::format("No bounce or rest within {:.0f} s of simulated time", next_event_horizon_s);
}

// Particle 0 of every variant goes back to its initial position with the launch velocity.
void relaunch(ui::LabSession& s) {
    Experiment& e = *s.experiment;
    if (e.runs().empty() || e.run(0).particle_count() == 0) return;
    // The running scene (the panels' edits are not applied yet).
    const Vec3 start = ui::first_particle(e.scene()).value_or(ParticleSpec{}).position;
    for (std::size_t v = 0; v < e.variant_count(); ++v) relaunch_particle(e.run(v), 0, start, s.launch_velocity);
    s.status_message = fmt::format("Launched particle 0 at ({:.3g}, {:.3g}, {:.3g}) m/s", s.launch_velocity.x,
                                   s.launch_velocity.y, s.launch_velocity.z);
}

}  // namespace

RequestOutcome perform_state_requests(ui::LabSession& s, const AfterSteps& after_step) {
    RequestOutcome out;
    ui::Requests& r = s.requests;
    if (!s.experiment) {
        r.reset = r.single_step = r.run_to_next_event = r.relaunch = false;
        return out;
    }
    if (r.reset) {
        s.experiment->reset();
        s.status_message = "Reset to the preset's initial state";
        out.state_jumped = true;
    }
    if (r.relaunch) {
        relaunch(s);
        out.state_jumped = true;
    }
    if (r.single_step) {
        s.paused = true;
        s.experiment->step_base(1);
        if (after_step) after_step();
    }
    if (r.run_to_next_event) run_to_next_event(s, after_step);
    r.reset = r.single_step = r.run_to_next_event = r.relaunch = false;
    return out;
}

}  // namespace pl::app
