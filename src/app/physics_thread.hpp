// Physics in its own thread, as MuJoCo's `simulate` runs it: the thread advances the running
// experiment at real time (x the time scale) in short slices, each holding one mutex; the UI
// takes the same mutex only while it reads or edits the session (requests, panels, the 3D
// view's buffers) and releases it before the GL work that dominates a frame (presenting,
// rasterising) and the frame-rate sleep. While the UI waits for the mutex the thread lets it in
// after its current slice, so an edit never waits longer than one slice (about 4 ms of steps,
// or one step when a single step takes longer).
//
// The trajectory does not depend on this: a run is a count of fixed steps (dt), and where the
// slices or frames fall between steps changes nothing (tests/replay_test.cpp). Deterministic
// runs (--fixed-frame-dt) and recordings step on the frame loop's fixed clock instead, with the
// thread idle (set_real_time(false)).
#pragma once

#include "app/physics_driver.hpp"
#include "ui/lab_session.hpp"

#include <atomic>
#include <cstdint>
#include <mutex>
#include <thread>

namespace pl::app {

// What the thread did since the UI last asked (shown in the status bar).
struct PhysicsStats {
    std::uint64_t steps = 0;    // base steps
    double simulated_s = 0.0;   // simulated time advanced
    double physics_ms = 0.0;    // wall time spent stepping
    bool behind = false;        // steps were dropped: physics cannot keep up at this time scale
};

class PhysicsThread {
public:
    // `before_steps` runs under the mutex before each slice (the trails follow a replaced
    // experiment); `after_steps` is advance_frame's hook. Both must outlive the thread.
    // `real_time`: the first value of set_real_time.
    PhysicsThread(ui::LabSession& session, const std::function<void()>& before_steps, const AfterSteps& after_steps,
                  bool real_time);
    ~PhysicsThread();  // stops and joins the thread
    PhysicsThread(const PhysicsThread&) = delete;
    PhysicsThread& operator=(const PhysicsThread&) = delete;

    // The UI's hold on the session: the thread finishes its slice and waits until this is released.
    std::unique_lock<std::mutex> lock_for_ui();

    // Under the lock: whether the thread follows real time (false: the frame loop steps).
    void set_real_time(bool on) { real_time_ = on; }
    // Under the lock: what the thread did since the last call.
    PhysicsStats take_stats();

    static constexpr double slice_budget_s = 0.004;  // wall time a slice may step before it lets the UI in

private:
    void run();
    void step_slice(double real_dt);
    double sleep_before_next_step() const;

    ui::LabSession& session_;
    const std::function<void()>& before_steps_;
    const AfterSteps& after_steps_;
    std::mutex mutex_;
    std::atomic<bool> ui_waiting_{false};
    std::atomic<bool> stop_{false};
    bool real_time_ = true;  // guarded by mutex_
    std::uint64_t owed_ = 0;              // base steps owed to real time, carried between slices
    const Experiment* stepped_ = nullptr;  // the experiment owed_ counts for
    PhysicsStats stats_;     // guarded by mutex_
    std::thread thread_;
};

}  // namespace pl::app
