#include "physics/stepping/step_replay.hpp"

#include "physics/model/terms/term_list.hpp"
#include "physics/stepping/particle_stepper.hpp"

namespace pl {

std::optional<StepTrace> replay_step(const Simulation& sim, std::size_t i, const StepStart& before) {
    const ParticleState& s = sim.state();
    if (sim.step_count() == 0 || i >= s.size() || s.frozen[i]) return std::nullopt;
    const Model& m = sim.model();
    // The generic kernel's body (generic_kernel.cpp, generic_step) for particle i alone.
    return terms::with_enabled_terms(m, [&]<class F>() -> std::optional<StepTrace> {
        const RoomBounds room(m.room);
        const double h = m.integrator.dt, t0 = static_cast<double>(sim.step_count() - 1) * h;
        const bool adaptive_on = m.integrator.method == Method::dopri5 && m.integrator.adaptive;
        std::vector<Event> events;
        AdaptiveStats adaptive;
        std::uint64_t contact_solves = 0;
        StepTrace trace;
        const StepContext ctx{&room,   &m.contact, m.integrator.method, m.integrator.rtol, m.integrator.atol,
                              &events, adaptive_on ? &adaptive : nullptr, &contact_solves, &trace};
        F f;
        TermInputs in = scene_inputs(m, &sim.wind());
        in.k = s.drag_k[i];
        in.re_scale = s.drag_re_scale[i];
        in.mass = s.mass[i];
        in.radius = s.radius[i];
        ParticleStep p;
        p.y.x = before.x;
        p.y.v = before.v;
        p.radius = s.radius[i];
        p.resting = before.resting;
        if (adaptive_on) p.step_hint = before.step_hint;
        const double spin_decay = m.drag.lift != LiftModel::none ? 1.0 / m.drag.spin_decay_s : 0.0;
        if (spin_matters(m)) p.spin = {{before.spin, t0, spin_decay}, s.inertia[i], 0.0};
        in.spin = &p.spin.clock;
        f.load(in);
        const ParticleStepper<F> stepper(ctx, f);
        if (!stepper.advance(p, static_cast<std::uint32_t>(i), t0, h)) return std::nullopt;
        if (p.y.x != s.position(i) || p.y.v != s.velocity(i)) return std::nullopt;
        return trace;
    });
}

}  // namespace pl
