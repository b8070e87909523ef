// The generic (reference) stepping kernel: one ParticleStepper::advance per particle, scalar.
// The fast kernel (fast_kernel.cpp) must give the same bits; tests/fast_kernel_test.cpp checks.
#include "physics/stepping/fast_kernel.hpp"
#include "physics/stepping/kernel.hpp"
#include "physics/stepping/particle_stepper.hpp"

namespace pl {

namespace {

// One step of the generic kernel for one combination of enabled force terms.
template <DragModel Drag, bool HasWind>
void generic_step(const KernelContext& k) {
    ParticleState& s = k.state;
    const Model& m = k.model;
    const RoomBounds room(m.room);
    Forces<Drag, HasWind> f;
    f.gravity = m.world.gravity;
    f.wind = &k.wind;
    AdaptiveStats adaptive;
    std::uint64_t contact_solves = 0;
    const bool adaptive_on = m.integrator.method == Method::dopri5 && m.integrator.adaptive;
    const StepContext ctx{&room,          &m.contact, m.integrator.method, m.integrator.rtol, m.integrator.atol,
                          k.events.events, adaptive_on ? &adaptive : nullptr, &contact_solves};
    const ParticleStepper<Forces<Drag, HasWind>> stepper(ctx, f);
    std::vector<double>* hints = adaptive_on ? &k.adaptive_hint : nullptr;
    const double t0 = k.time(), h = m.integrator.dt;

    for (std::size_t i = 0; i < s.size(); ++i) {
        if (s.frozen[i]) continue;
        f.drag = {s.drag_k[i], s.drag_re_scale[i]};
        ParticleStep p = load_step(s, i, hints, s.radius[i]);
        stepper.advance(p, static_cast<std::uint32_t>(i), t0, h);
        if (!is_finite(p.y)) {
            // Keep the last finite state and stop stepping this particle.
            s.frozen[i] = 1;
            k.events.events->push_back(
                {t0, static_cast<std::uint32_t>(i), -1, EventKind::frozen, glm::length(s.velocity(i)), 0.0});
            k.warnings.raise(WarningKind::frozen, static_cast<std::uint32_t>(i), t0);
            continue;
        }
        store_step<Drag, HasWind>(s, i, p, hints, s.mass[i]);
    }
    add_counts(k.counters, f, adaptive, contact_solves);
}

template <DragModel Drag, bool HasWind>
void step_kernel(const KernelContext& k, std::uint32_t steps) {
    for (std::uint32_t n = 0; n < steps; ++n) {
        generic_step<Drag, HasWind>(k);
        k.end_step();
    }
}

template <DragModel Drag>
StepKernel pick_wind(bool has_wind) {
    return has_wind ? &step_kernel<Drag, true> : &step_kernel<Drag, false>;
}

}  // namespace

StepKernel pick_kernel(const Model& m, KernelChoice choice) {
    if (choice == KernelChoice::fast) return pick_fast_kernel(m);
    // Wind acts only through drag: without drag the wind field is never consulted.
    const bool wind = m.world.wind.kind != WindKind::none && m.drag.model != DragModel::none;
    switch (m.drag.model) {
        case DragModel::none: return &step_kernel<DragModel::none, false>;
        case DragModel::linear: return pick_wind<DragModel::linear>(wind);
        case DragModel::quadratic: return pick_wind<DragModel::quadratic>(wind);
        case DragModel::sphere_re: return pick_wind<DragModel::sphere_re>(wind);
    }
    return &step_kernel<DragModel::none, false>;
}

}  // namespace pl
