#include "physics/stepping/simulation.hpp"

#include "physics/model/drag.hpp"
#include "physics/stepping/energy.hpp"
#include "physics/stepping/fast_kernel.hpp"
#include "physics/stepping/particle_stepper.hpp"

#include <algorithm>
#include <cmath>

namespace pl {

namespace {


// One step of the generic kernel for one combination of enabled force terms.
template <DragModel Drag, bool HasWind>
void generic_step(Simulation& sim) {
    ParticleState& s = sim.mutable_state();
    const Model& m = sim.model();
    const RoomBounds room(m.room);
    Forces<Drag, HasWind> f;
    f.gravity = m.world.gravity;
    f.wind = &sim.wind();
    AdaptiveStats adaptive;
    std::uint64_t contact_solves = 0;
    const bool adaptive_on = m.integrator.method == Method::dopri5 && m.integrator.adaptive;
    const StepContext ctx{&room,         &m.contact, m.integrator.method, m.integrator.rtol, m.integrator.atol,
                          &sim.event_sink(), adaptive_on ? &adaptive : nullptr, &contact_solves};
    const ParticleStepper<Forces<Drag, HasWind>> stepper(ctx, f);
    std::vector<double>& hints = sim.adaptive_step_hint();
    const double t0 = sim.time(), h = m.integrator.dt;

    for (std::size_t i = 0; i < s.size(); ++i) {
        if (s.frozen[i]) continue;
        f.drag = {s.drag_k[i], s.drag_re_scale[i]};
        ParticleStep p = load_step(s, i, adaptive_on ? &hints : nullptr, s.radius[i]);
        stepper.advance(p, static_cast<std::uint32_t>(i), t0, h);
        if (!is_finite(p.y)) {
            // Keep the last finite state and stop stepping this particle.
            s.frozen[i] = 1;
            sim.event_sink().push_back(
                {t0, static_cast<std::uint32_t>(i), -1, EventKind::frozen, glm::length(s.velocity(i)), 0.0});
            sim.raise(WarningKind::frozen, static_cast<std::uint32_t>(i));
            continue;
        }
        store_step<Drag, HasWind>(s, i, p, adaptive_on ? &hints : nullptr, s.mass[i]);
    }
    add_counts(sim.mutable_counters(), f, adaptive, contact_solves);
}

template <DragModel Drag, bool HasWind>
void step_kernel(Simulation& sim, std::uint32_t steps) {
    for (std::uint32_t k = 0; k < steps; ++k) {
        generic_step<Drag, HasWind>(sim);
        sim.finish_step();
    }
}

template <DragModel Drag>
StepKernel pick_wind(bool has_wind) {
    return has_wind ? &step_kernel<Drag, true> : &step_kernel<Drag, false>;
}

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

}  // namespace

Simulation::Simulation(Model model, const std::vector<ParticleSpec>& particles)
    : model_(std::move(model)), wind_(model_.world.wind, model_.room) {
    state_.resize(particles.size());
    for (std::size_t i = 0; i < particles.size(); ++i) {
        const ParticleSpec& p = particles[i];
        state_.set_position(i, p.position);
        state_.set_velocity(i, p.velocity);
        state_.mass[i] = p.mass;
        state_.radius[i] = p.radius;
        const DragCoefficients c = drag_coefficients(model_.drag, model_.world.air, p.mass, p.radius);
        state_.drag_k[i] = c.k;
        state_.drag_re_scale[i] = c.re_scale;
        state_.initial_energy[i] = kinetic_energy(p.mass, p.velocity) +
                                   potential_energy(model_.world.gravity, model_.room, p.mass, p.position);
    }
    identical_particles_ = std::all_of(particles.begin(), particles.end(), [&](const ParticleSpec& p) {
        return p.mass == particles.front().mass && p.radius == particles.front().radius;
    });  // drag coefficients are functions of mass and radius
    warned_.assign(particles.size(), 0);
    if (model_.integrator.method == Method::dopri5) adaptive_step_hint_.assign(particles.size(), 0.0);
    kernel_ = pick_kernel(model_, kernel_choice_);
    monitor();
}

void Simulation::set_kernel(KernelChoice choice) {
    kernel_choice_ = choice;
    kernel_ = pick_kernel(model_, kernel_choice_);
}

void Simulation::step() { step_n(1); }

void Simulation::step_n(std::uint64_t n) {
    // The monitor reads the state after the steps it samples, so a kernel call ends at each of
    // them; in between, the kernel may take the steps in any order that gives the same bits.
    const std::uint64_t period = monitor_period();
    while (n > 0) {
        const std::uint64_t to_sample = period - steps_ % period;
        const std::uint64_t k = std::min({n, to_sample, steps_per_kernel_call});
        kernel_(*this, static_cast<std::uint32_t>(k));
        monitor();
        n -= k;
    }
}

std::uint64_t Simulation::steps_to(double t) const {
    std::uint64_t k = 0;
    while (static_cast<double>(steps_ + k + 1) * dt() <= t * (1.0 + 1e-12)) ++k;
    return k;
}

void Simulation::finish_step() {
    ++steps_;
    if (events_.size() > max_pending_events) {
        // Nobody is draining: keep the newest events, count the rest, stay bounded in memory.
        const std::size_t drop = events_.size() - max_pending_events / 2;
        events_.erase(events_.begin(), events_.begin() + static_cast<std::ptrdiff_t>(drop));
        dropped_events_ += drop;
    }
}

void Simulation::run_until(double t) {
    const double target = std::round(t / dt() * (1.0 + 1e-12));
    if (static_cast<double>(steps_) < target) step_n(static_cast<std::uint64_t>(target) - steps_);
}

void Simulation::set_velocity(std::size_t i, const Vec3& v) {
    state_.set_velocity(i, v);
    // Walls the new velocity points away from no longer hold the particle; walls it points
    // into keep it resting with the normal component removed on the next step.
    for (int w = 0; w < wall_count; ++w) {
        if (!(state_.resting[i] & (1u << w))) continue;
        if (glm::dot(v, RoomBounds::inward_normal(w)) > 0.0) {
            state_.resting[i] &= static_cast<std::uint8_t>(~(1u << w));
            events_.push_back({time(), static_cast<std::uint32_t>(i), static_cast<std::int8_t>(w), EventKind::lift,
                               glm::length(v), glm::length(v)});
        }
    }
}

Vec3 Simulation::acceleration(std::size_t i) const {
    Vec3 a = model_.world.gravity;
    if (model_.drag.model == DragModel::none) return a;
    const Vec3 u = air_velocity(i);
    const double speed = glm::length(u);
    const DragCoefficients c{state_.drag_k[i], state_.drag_re_scale[i]};
    double rate = 0.0;
    switch (model_.drag.model) {
        case DragModel::none: break;
        case DragModel::linear: rate = c.k; break;
        case DragModel::quadratic: rate = c.k * speed; break;
        case DragModel::sphere_re: rate = c.k * sphere_cd_times_re(c.re_scale * speed); break;
    }
    return a - rate * u;
}

Vec3 Simulation::air_velocity(std::size_t i) const { return state_.velocity(i) - wind_.at(state_.position(i), time()); }

double Simulation::reynolds_number(std::size_t i) const {
    if (model_.drag.model == DragModel::none) return 0.0;
    return state_.drag_re_scale[i] * glm::length(air_velocity(i));
}

std::vector<Event> Simulation::drain_events() {
    std::vector<Event> out;
    out.swap(events_);
    // The next steps produce about as many: room for them, so that the sink does not grow from
    // empty after every drain (reallocating and touching fresh pages, the dearest part of an
    // event in a large scene).
    events_.reserve(out.size());
    return out;
}

void Simulation::raise(WarningKind kind, std::uint32_t particle, double value) {
    const auto bit = static_cast<std::uint8_t>(1u << static_cast<unsigned>(kind));
    if (warned_[particle] & bit) return;
    warned_[particle] |= bit;
    warnings_.push_back({kind, particle, time(), value});
}

}  // namespace pl
