#include "app/physics_thread.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace pl::app {

namespace {

using Clock = std::chrono::steady_clock;

constexpr double max_gap_s = 0.25;        // longer gaps (a debugger, a suspended machine) are not caught up
constexpr double idle_poll_s = 0.005;     // paused or on the frame loop's clock: how often to look again
constexpr double max_sleep_s = 0.002;     // the longest nap between slices while running

}  // namespace

PhysicsThread::PhysicsThread(ui::LabSession& session, const std::function<void()>& before_steps,
                             const AfterSteps& after_steps, bool real_time)
    : session_(session), before_steps_(before_steps), after_steps_(after_steps), real_time_(real_time),
      thread_([this] { run(); }) {}

PhysicsThread::~PhysicsThread() {
    stop_ = true;
    thread_.join();
}

std::unique_lock<std::mutex> PhysicsThread::lock_for_ui() {
    ui_waiting_ = true;
    std::unique_lock<std::mutex> lock(mutex_);
    ui_waiting_ = false;
    return lock;
}

PhysicsStats PhysicsThread::take_stats() {
    const PhysicsStats out = stats_;
    stats_ = {};
    return out;
}

// Steps the clock owes are carried from slice to slice (a slice ends when its budget runs out, or
// the UI held the mutex for a long frame), up to max_gap_s of real time; only what exceeds that
// is dropped, and the UI hears it as "behind".
void PhysicsThread::step_slice(double real_dt) {
    ui::LabSession& s = session_;
    if (!real_time_ || !s.experiment || s.paused || s.experiment.get() != stepped_) {
        owed_ = 0;  // the real time passes unused: no catch-up later, nor steps owed by another experiment
        stepped_ = s.experiment.get();
        if (!real_time_ || !s.experiment || s.paused) return;
    }
    if (before_steps_) before_steps_();
    Experiment& e = *s.experiment;
    e.clock().time_scale = s.time_scale;
    const FixedStepClock::Tick tick = e.clock().advance(real_dt, e.base_dt());
    const auto max_owed = static_cast<std::uint64_t>(std::ceil(max_gap_s * s.time_scale / e.base_dt()));
    const bool dropped = tick.behind || owed_ + tick.steps > max_owed;
    owed_ = std::min(owed_ + tick.steps, max_owed);
    const double t0 = e.time();
    const FrameAdvance a = run_steps(e, owed_, slice_budget_s, after_steps_);
    owed_ -= a.steps;
    stats_.steps += a.steps;
    stats_.simulated_s += e.time() - t0;
    stats_.physics_ms += a.physics_ms;
    stats_.behind = stats_.behind || dropped;
}

// Real seconds until the clock owes the next step (the backlog is < dt after a slice).
double PhysicsThread::sleep_before_next_step() const {
    const ui::LabSession& s = session_;
    if (!real_time_ || !s.experiment || s.paused) return idle_poll_s;
    if (owed_ > 0) return 0.0;  // catching up
    Experiment& e = *s.experiment;
    const double owed_s = (e.base_dt() - e.clock().backlog()) / std::max(s.time_scale, 1e-9);
    return std::clamp(owed_s, 0.0, max_sleep_s);
}

void PhysicsThread::run() {
    Clock::time_point last = Clock::now();
    while (!stop_) {
        double sleep_s = 0.0;
        {
            const std::lock_guard<std::mutex> lock(mutex_);
            const Clock::time_point now = Clock::now();
            const double real_dt = std::min(std::chrono::duration<double>(now - last).count(), max_gap_s);
            last = now;
            step_slice(real_dt);
            sleep_s = sleep_before_next_step();
        }
        // A waiting UI goes first: it clears the flag once it holds the mutex (std::mutex is not
        // fair, so without this a thread that is behind could take it again at once).
        while (ui_waiting_ && !stop_) std::this_thread::yield();
        if (sleep_s > 0.0) std::this_thread::sleep_for(std::chrono::duration<double>(sleep_s));
    }
}

}  // namespace pl::app
