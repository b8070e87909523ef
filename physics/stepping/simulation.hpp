// Simulation: advances one Model's particles by fixed steps of model.integrator.dt.
// The force sum is assembled from the model once, at construction: terms the model does not
// enable (drag, wind) are compiled out of the stepping kernel and never evaluated.
#pragma once

#include "physics/model/drag.hpp"
#include "physics/model/scene.hpp"
#include "physics/model/wind.hpp"
#include "physics/stepping/events.hpp"
#include "physics/stepping/kernel.hpp"
#include "physics/stepping/particle_state.hpp"
#include "physics/stepping/warnings.hpp"

#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace pl {

namespace collide {
class CollisionPass;
}

// What the monitor's scan found in a range of particles: the largest drag stiffness and, in
// particle order, the particles that crossed a limit they have not been warned about yet.
struct MonitorScan {
    double max_stiffness = 0.0;
    ReRange reynolds{INFINITY, 0.0};  // of the particles in flight; empty (lo > hi) if none flew
    std::vector<std::uint32_t> suspects;
};

class Simulation {
public:
    Simulation(Model model, const std::vector<ParticleSpec>& particles);
    // Out of line: the collision pass is an incomplete type here (its headers stay out of the
    // many files that include this one).
    ~Simulation();
    Simulation(Simulation&&) noexcept;
    Simulation& operator=(Simulation&&) noexcept;

    void step();  // exactly one fixed step of model().integrator.dt
    // n steps; the same result as n calls of step(). Large scenes advance each block of
    // particles through several steps while it is in cache (up to steps_per_kernel_call per
    // kernel call, ending where the monitor samples), so this is the faster way to take many.
    void step_n(std::uint64_t n);
    static constexpr std::uint64_t steps_per_kernel_call = 32;
    // Steps until time() >= t (whole steps only; t is rounded to the step grid).
    void run_until(double t);
    // How many whole steps from now end at or before time t (the lockstep rule of Experiment).
    std::uint64_t steps_to(double t) const;

    double time() const { return static_cast<double>(steps_) * model_.integrator.dt; }
    double dt() const { return model_.integrator.dt; }
    std::uint64_t step_count() const { return steps_; }
    const Model& model() const { return model_; }
    const ParticleState& state() const { return state_; }
    std::size_t particle_count() const { return state_.size(); }
    const WindField& wind() const { return wind_; }
    // Whether every particle has the same mass, radius and drag coefficients (set at
    // construction, the only place they are written): kernels then read them once.
    bool identical_particles() const { return identical_particles_; }

    // Threads for the particle loop: 0 = all hardware threads (the default), 1 = single-threaded.
    // Results are bit-identical for every setting; small scenes always run on one thread.
    void set_threads(int threads) { threads_ = threads < 0 ? 0 : threads; }
    int threads() const { return threads_; }
    void set_kernel(KernelChoice choice);
    KernelChoice kernel() const { return kernel_choice_; }

    // Sets a particle's velocity (a kick); it leaves any wall it is pushed away from.
    void set_velocity(std::size_t i, const Vec3& v);
    // Net acceleration a particle feels at its current state (no contact forces).
    Vec3 acceleration(std::size_t i) const;
    // A particle's velocity relative to the air at its position now (v - wind).
    Vec3 air_velocity(std::size_t i) const;
    // Reynolds number of a particle's motion relative to the air now (0 without drag).
    double reynolds_number(std::size_t i) const;

    // Events since the last drain (the simulation appends; consumers take them).
    const std::vector<Event>& events() const { return events_; }
    std::vector<Event> drain_events();
    // At most this many undrained events are kept; older ones are dropped and counted.
    static constexpr std::size_t max_pending_events = EventSink::max_pending;
    std::uint64_t dropped_events() const { return dropped_events_; }
    const std::vector<Warning>& warnings() const { return warnings_; }
    const ForceCounters& counters() const { return counters_; }
    // Adaptive Dormand-Prince: the internal step particle i's next step starts with (0: none yet).
    double adaptive_step_hint(std::size_t i) const { return i < adaptive_step_hint_.size() ? adaptive_step_hint_[i] : 0.0; }
    // Particle-particle collisions (model().collisions.enabled): impulses applied in the last step
    // and since the start. Both stay 0 without collisions.
    std::uint64_t collisions_last_step() const { return collisions_last_step_; }
    std::uint64_t collisions_total() const { return collisions_total_; }
    // The pile: resting contacts carrying a load in the last step, and sleeping particles (a
    // sleeping particle has 1 in `asleep()`; empty without collisions). `collision_pass()` is
    // null without collisions (its contacts, for drawing them).
    std::uint64_t resting_contacts() const;
    std::size_t asleep_count() const;
    const std::vector<std::uint8_t>& asleep() const;
    const collide::CollisionPass* collision_pass() const { return collisions_.get(); }
    // Particle i is at rest: not frozen, no velocity, and held there, on a wall (static friction)
    // or asleep in a pile. The studies' "time to rest" counts from the event that left it so.
    bool at_rest(std::size_t i) const;

    // Reynolds numbers the monitor has seen (at its samples, over the moving particles that are
    // neither on a wall nor frozen); lo > hi while none has flown, and without drag.
    ReRange observed_reynolds() const { return reynolds_; }
    // Largest drag stiffness k (1/s) seen so far, over all particles.
    double max_drag_stiffness() const { return max_stiffness_; }

    // The stepping kernel alone for `steps` steps (<= steps_per_kernel_call), without the
    // monitor's checks after it: what the engine benchmark times against the whole step.
    void run_kernel(std::uint32_t steps) { kernel_(context(), steps); }

private:
    friend void relaunch_particle(Simulation& sim, std::size_t i, const Vec3& position, const Vec3& velocity);
    KernelContext context();  // the data a kernel call works on
    void monitor();  // NaN guard, validity ranges, stability guard
    // The explicit-Euler rest trap (no_rest_dt): warns each particle that bounces on a floor
    // (a wall gravity presses on) in the events from `first` on, when the model's dt is in it.
    void watch_rest(std::size_t first);
    std::uint64_t monitor_period() const;  // it samples the steps that are multiples of this
    // Walls that velocity v points away from stop holding particle i (a kick or a collision).
    void release_from_walls(std::size_t i, const Vec3& v);
    // Where the events stood before a kernel call, and the index of the first event the call
    // added (the cap may have dropped older ones meanwhile).
    struct EventMark {
        std::size_t size;
        std::uint64_t dropped;
    };
    EventMark mark_events() const { return {events_.size(), dropped_events_}; }
    std::size_t events_since(const EventMark& mark) const;
    void collide_step();  // one kernel step followed by the collision pass
    // The step's events from `first` on, after the collision pass: a pile's contacts are not
    // bounces and stops; its balls stop when they fall asleep.
    void book_pile_events(std::size_t first);

    Model model_;
    WindField wind_;
    ParticleState state_;
    StepKernel kernel_ = nullptr;
    KernelChoice kernel_choice_ = KernelChoice::fast;
    int threads_ = 0;
    bool identical_particles_ = false;
    std::uint64_t steps_ = 0;
    std::vector<Event> events_;
    std::uint64_t dropped_events_ = 0;
    std::vector<Warning> warnings_;
    std::vector<WarningBits> warned_;  // per particle: bit per WarningKind
    std::uint8_t no_rest_floors_ = 0;    // walls on which the model cannot come to rest (watch_rest)
    ForceCounters counters_;
    ReRange reynolds_{INFINITY, 0.0};
    double max_stiffness_ = 0.0;
    std::vector<MonitorScan> scans_;  // one per particle range, kept from sample to sample
    std::vector<double> adaptive_step_hint_;  // dopri5: last accepted internal step per particle
    std::unique_ptr<collide::CollisionPass> collisions_;  // only where model().collisions.enabled
    std::uint64_t collisions_last_step_ = 0, collisions_total_ = 0;
};

}  // namespace pl
