// The generic (reference) stepping kernel: one ParticleStepper::advance per particle, scalar.
// The fast kernel (fast_kernel.cpp) must give the same bits; tests/fast_kernel_test.cpp checks.
#include "physics/model/air_model.hpp"
#include "physics/model/terms/term_list.hpp"
#include "physics/stepping/fast_kernel.hpp"
#include "physics/stepping/kernel.hpp"
#include "physics/stepping/particle_stepper.hpp"

namespace pl {

namespace {

// One step of the generic kernel for one combination of enabled force terms.
template <class F>
void generic_step(const KernelContext& k) {
    ParticleState& s = k.state;
    const Model& m = k.model;
    const RoomBounds room(m.room);
    F f;
    TermInputs in = scene_inputs(m, &k.wind);
    AdaptiveStats adaptive;
    std::uint64_t contact_solves = 0;
    const bool adaptive_on = m.integrator.method == Method::dopri5 && m.integrator.adaptive;
    const StepContext ctx{&room,          &m.contact, m.integrator.method, m.integrator.rtol, m.integrator.atol,
                          k.events.events, adaptive_on ? &adaptive : nullptr, &contact_solves};
    const ParticleStepper<F> stepper(ctx, f);
    std::vector<double>* hints = adaptive_on ? &k.adaptive_hint : nullptr;
    const double t0 = k.time(), h = m.integrator.dt;

    const bool spinning = spin_matters(m);
    const double spin_decay = m.drag.lift != LiftModel::none ? 1.0 / m.drag.spin_decay_s : 0.0;

    for (std::size_t i = 0; i < s.size(); ++i) {
        if (s.frozen[i]) continue;
        in.k = s.drag_k[i];
        in.re_scale = s.drag_re_scale[i];
        in.mass = s.mass[i];
        in.radius = s.radius[i];
        ParticleStep p = load_step(s, i, hints, s.radius[i]);
        // The spin couples to the translation of the inertial mass M (the added mass, terms/
        // air_column.hpp): I = k m R^2 = (k m / M) M R^2. Its losses are per kg of M.
        const double inertial = F::has_air_column ? inertial_mass(m.world, m.room, s.mass[i], s.radius[i], p.y.x.y) : s.mass[i];
        if (spinning) p.spin = {{s.spin(i), t0, spin_decay}, s.inertia[i] * (s.mass[i] / inertial), 0.0};
        in.spin = &p.spin.clock;
        f.load(in);
        const bool finished = stepper.advance(p, static_cast<std::uint32_t>(i), t0, h);
        if (const StepFault fault = step_fault(p.y, finished); fault != StepFault::none) {
            // Keep the last good state and stop stepping this particle.
            const Warning w = freeze_particle(s, static_cast<std::uint32_t>(i), t0, fault, p.y, *k.events.events);
            k.warnings.raise(w.kind, w.particle, w.t, w.value);
            continue;
        }
        if constexpr (F::has_air_column) {
            // Drag and air work per kg of m; bounce and friction, from velocity changes, per kg of M.
            store_step<F>(s, i, p, hints, s.mass[i], inertial_mass(m.world, m.room, s.mass[i], s.radius[i], p.y.x.y));
        } else {
            store_step<F>(s, i, p, hints, s.mass[i]);
        }
        if (spinning) {
            s.set_spin(i, p.spin.restart(t0 + h, s.radius[i]));
            s.dissipated_rolling[i] += inertial * p.spin.rolling_loss;
            s.dissipated_drag[i] += inertial * p.spin.decay_loss;
        }
    }
    add_counts(k.counters, f, adaptive, contact_solves);
}

template <class F>
void step_kernel(const KernelContext& k, std::uint32_t steps) {
    for (std::uint32_t n = 0; n < steps; ++n) {
        generic_step<F>(k);
        k.end_step();
    }
}

}  // namespace

StepKernel pick_kernel(const Model& m, KernelChoice choice) {
    // The fast kernel steps point masses with a constant e; spin or e(v_n) run here.
    if (choice == KernelChoice::fast && !needs_generic_kernel(m)) return pick_fast_kernel(m);
    return terms::with_enabled_terms(m, []<class F>() -> StepKernel { return &step_kernel<F>; });
}

}  // namespace pl
