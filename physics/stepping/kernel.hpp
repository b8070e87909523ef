// The stepping-kernel interface: what a kernel reads and writes, as plain data. Simulation owns
// the data and builds a KernelContext for each call; kernels (generic_kernel.cpp,
// fast_kernel.cpp) see only this, never the Simulation, so the include graph runs one way:
// simulation.hpp -> kernel.hpp <- kernels.
#pragma once

#include "physics/model/scene.hpp"
#include "physics/model/terms/counters.hpp"
#include "physics/model/wind.hpp"
#include "physics/stepping/events.hpp"
#include "physics/stepping/particle_state.hpp"
#include "physics/stepping/warnings.hpp"

#include <cstdint>
#include <vector>

namespace pl {

// Where a kernel's events go. At most max_pending undrained events are kept: end_step drops
// the oldest (and counts them) when nobody drains, so memory stays bounded.
struct EventSink {
    std::vector<Event>* events;
    std::uint64_t* dropped;
    static constexpr std::size_t max_pending = 1u << 20;
    void end_step() const;
};

// Where a kernel's warnings go: once per particle and kind (`warned` holds a bit per kind), and
// once more for drag validity above the range (bit drag_above_range_bit): below it (a slow
// particle near an apex, where drag is negligible) the warning is mostly a harmless note, and it
// must not mask the real one of the same particle leaving the range upwards later.
struct WarningSink {
    std::vector<Warning>* warnings;
    std::vector<WarningBits>* warned;
    static constexpr unsigned drag_above_range_bit = 15;
    void raise(WarningKind kind, std::uint32_t particle, double t, double value = 0.0, bool above_range = false) const;
};
static_assert(warning_kind_count <= WarningSink::drag_above_range_bit, "a bit per kind below the extra one");

// Everything one kernel call works on.
struct KernelContext {
    ParticleState& state;
    const Model& model;  // constants: room, world, drag, contact, integrator
    const WindField& wind;
    std::vector<double>& adaptive_hint;  // dopri5: last accepted internal step per particle (else empty)
    EventSink events;
    WarningSink warnings;
    ForceCounters& counters;
    std::uint64_t& step;  // steps taken so far; end_step() advances it
    int threads;          // 0 = all hardware threads
    // Whether every particle has the same mass, radius and drag coefficients (kernels then
    // read them once).
    bool identical_particles;

    double time() const { return static_cast<double>(step) * model.integrator.dt; }
    // Ends one step of the call: the step counter and the cap on undrained events.
    void end_step() const {
        ++step;
        events.end_step();
    }
};

// A stepping kernel advances by `steps` (>= 1) fixed steps. For each step, in order, it appends
// that step's events, raises its warnings and calls end_step(), so that one call of `steps`
// steps leaves exactly what `steps` calls of one step would.
using StepKernel = void (*)(const KernelContext&, std::uint32_t steps);

// fast: the production kernel (fast_kernel.hpp: vectorised flight, threads); generic: the
// scalar reference kernel, one ParticleStepper::advance per particle. Results are bit-identical.
enum class KernelChoice : std::uint8_t { fast, generic };

// The kernel for the model's force terms and method (never null).
StepKernel pick_kernel(const Model& model, KernelChoice choice);

}  // namespace pl
