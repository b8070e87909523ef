#include "physics/stepping/simulation.hpp"

#include "physics/model/air_model.hpp"
#include "physics/collide/collision_pass.hpp"
#include "physics/model/drag.hpp"
#include "physics/model/model_check.hpp"
#include "physics/model/terms/term_list.hpp"
#include "physics/stepping/contact.hpp"
#include "physics/stepping/energy.hpp"
#include "physics/stepping/fast_kernel.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

namespace pl {

Simulation::Simulation(Model model, const std::vector<ParticleSpec>& particles)
    : model_((check_model(model, particles), std::move(model))), wind_(model_.world.wind, model_.room) {
    state_.resize(particles.size());
    for (std::size_t i = 0; i < particles.size(); ++i) {
        const ParticleSpec& p = particles[i];
        state_.set_position(i, p.position);
        state_.set_velocity(i, p.velocity);
        state_.mass[i] = p.mass;
        state_.radius[i] = p.radius;
        state_.set_spin(i, p.spin);
        state_.inertia[i] = inertia_factor(p.inertia);
        // ISA air: the coefficients at the starting height (the monitor's Re and stiffness; the
        // force terms recompute them at every height, terms/air_column.hpp).
        const Air air = local_air(model_.world.air, model_.room, p.position.y);
        const DragCoefficients c = drag_coefficients(model_.drag, air, p.mass, p.radius);
        state_.drag_k[i] = c.k;
        state_.drag_re_scale[i] = c.re_scale;
        state_.inertial_mass[i] = inertial_mass(model_.world, model_.room, p.mass, p.radius, p.position.y);
        state_.initial_energy[i] = kinetic_energy(state_.inertial_mass[i], p.velocity) +
                                   potential_energy(model_.world.gravity, model_.room, p.mass, p.position) +
                                   spin_energy(p.mass, p.radius, state_.inertia[i], p.spin);
    }
    identical_particles_ = std::all_of(particles.begin(), particles.end(), [&](const ParticleSpec& p) {
        return p.mass == particles.front().mass && p.radius == particles.front().radius;
    });  // drag coefficients are functions of mass and radius
    warned_.assign(particles.size(), 0);
    if (model_.integrator.method == Method::dopri5) adaptive_step_hint_.assign(particles.size(), 0.0);
    kernel_ = pick_kernel(model_, kernel_choice_);
    if (model_.collisions.enabled) {
        collisions_ = std::make_unique<collide::CollisionPass>(particles.size());
        state_.collision_work.assign(particles.size(), 0.0);
    }
    if (dt() > no_rest_dt(model_))
        for (int w = 0; w < wall_count; ++w)
            if (glm::dot(model_.world.gravity, RoomBounds::inward_normal(w)) < 0.0)
                no_rest_floors_ |= static_cast<std::uint8_t>(1u << w);
    monitor();
}

Simulation::~Simulation() = default;
Simulation::Simulation(Simulation&&) noexcept = default;
Simulation& Simulation::operator=(Simulation&&) noexcept = default;

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
        // With collisions, the pass follows every step: one step per kernel call.
        const std::uint64_t k = collisions_ ? 1 : std::min({n, to_sample, steps_per_kernel_call});
        const EventMark mark = mark_events();
        if (collisions_) collide_step();
        else kernel_(context(), static_cast<std::uint32_t>(k));
        if (no_rest_floors_) watch_rest(events_since(mark));
        monitor();
        n -= k;
    }
}

std::uint64_t Simulation::steps_to(double t) const {
    // The largest n with n dt <= t (1 + 1e-12), less the steps taken (n dt grows with n, so this
    // is where one-at-a-time counting would stop): the floor of the quotient, corrected by one
    // with the product the steps are timed by (the quotient may round across an integer).
    if (std::isnan(t)) throw std::invalid_argument("steps_to: t must be a number, got NaN");
    const double limit = t * (1.0 + 1e-12);
    const double q = std::max(0.0, std::floor(limit / dt()));
    if (!(q < 0x1p63)) throw std::invalid_argument(fmt::format("steps_to: t = {} is beyond 2^63 steps", t));
    auto n = static_cast<std::uint64_t>(q);
    if (static_cast<double>(n + 1) * dt() <= limit) ++n;
    else if (n > 0 && static_cast<double>(n) * dt() > limit) --n;
    return n > steps_ ? n - steps_ : 0;
}

KernelContext Simulation::context() {
    return {state_,    model_, wind_,  adaptive_step_hint_, {&events_, &dropped_events_}, {&warnings_, &warned_},
            counters_, steps_, threads_, identical_particles_};
}

void Simulation::run_until(double t) {
    const double target = std::round(t / dt() * (1.0 + 1e-12));
    if (static_cast<double>(steps_) < target) step_n(static_cast<std::uint64_t>(target) - steps_);
}

void Simulation::collide_step() {
    const EventMark mark = mark_events();
    collisions_->begin_step(state_, model_, thread_count(threads_));
    kernel_(context(), 1);
    const std::size_t step_events = events_since(mark);
    // The kernel stepped the sleeping particles too; the pass puts them back where they slept,
    // so what the kernel reported of them (a bounce off a wall a pile pressed them against) did
    // not happen.
    const std::vector<std::uint8_t>& asleep = collisions_->asleep();
    events_.erase(std::remove_if(events_.begin() + static_cast<std::ptrdiff_t>(step_events), events_.end(),
                                 [&asleep](const Event& e) { return asleep[e.particle] != 0; }),
                  events_.end());
    collisions_last_step_ = collisions_->end_step(state_, model_, dt(), thread_count(threads_));
    collisions_total_ += collisions_last_step_;
    for (const std::uint32_t i : collisions_->moved()) release_from_walls(i, state_.velocity(i));
    book_pile_events(step_events);
    const double step_start = time() - dt();
    for (Event e : collisions_->wall_bounces()) {
        e.t += step_start;
        events_.push_back(e);
    }
    const WarningSink sink{&warnings_, &warned_};
    for (const collide::CollisionPass::DeepOverlap& o : collisions_->deep_overlaps())
        sink.raise(WarningKind::collision_overlap, o.a, time(), o.share);
    for (const collide::PairCrossing& c : collisions_->crossings())
        sink.raise(WarningKind::collision_crossing, c.a, time(), c.travel);
}

std::size_t Simulation::events_since(const EventMark& mark) const {
    // Events the cap dropped since the mark were the oldest: the new ones start that much earlier.
    return mark.size - std::min<std::uint64_t>(mark.size, dropped_events_ - mark.dropped);
}

void Simulation::book_pile_events(std::size_t first) {
    // A stop is the end of a particle's motion. A ball in a settling pile is stopped by the
    // floor's friction in the kernel and pushed on by its neighbours' contacts, every few steps
    // (tens of "stops" per ball, from speeds down to 1e-20 m/s, none of them its last): its
    // stillness is the islands' to judge. So the stops of particles the collision pass acted on
    // this step (struck, or in a contact that pushed) are dropped, and each particle of a pile
    // whose island falls asleep stops there, at the end of this step (held from the next step
    // on). A particle alone on a wall keeps the kernel's stop. Likewise the bounces of such
    // particles slower than an impact (CollisionPass::impact_speed: what gravity adds in two
    // steps): a pile pressing its balls against the walls made them "bounce" at g dt / 2 every
    // few steps (60% of granular_pile.json's bounce events). Their energy stays in the ledger.
    const collide::CollisionPass& pass = *collisions_;
    const double impact = collide::CollisionPass::impact_speed(model_, dt());
    const auto undone = [&pass, impact](const Event& e) {
        const bool contact = e.kind == EventKind::stop || (e.kind == EventKind::bounce && e.speed_in < impact);
        return contact && pass.moved(e.particle);
    };
    events_.erase(std::remove_if(events_.begin() + static_cast<std::ptrdiff_t>(first), events_.end(), undone),
                  events_.end());
    for (const std::uint32_t i : pass.fell_asleep())
        events_.push_back({time(), i, -1, EventKind::stop, glm::length(state_.velocity(i)), 0.0});
}

bool Simulation::at_rest(std::size_t i) const {
    const bool held = state_.resting[i] != 0 || (collisions_ && collisions_->asleep()[i]);
    return held && !state_.frozen[i] && state_.velocity(i) == Vec3(0.0);
}

std::uint64_t Simulation::resting_contacts() const { return collisions_ ? collisions_->resting_contacts() : 0; }
std::size_t Simulation::asleep_count() const { return collisions_ ? collisions_->asleep_count() : 0; }
const std::vector<std::uint8_t>& Simulation::asleep() const {
    static const std::vector<std::uint8_t> none;
    return collisions_ ? collisions_->asleep() : none;
}

void Simulation::set_velocity(std::size_t i, const Vec3& v) {
    state_.set_velocity(i, v);
    if (collisions_) collisions_->wake(static_cast<std::uint32_t>(i));
    release_from_walls(i, v);
}

void Simulation::release_from_walls(std::size_t i, const Vec3& v) {
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
    return terms::with_enabled_terms(model_, [&]<class F>() {
        F f;
        TermInputs in = scene_inputs(model_, &wind_);
        in.k = state_.drag_k[i];
        in.re_scale = state_.drag_re_scale[i];
        in.mass = state_.mass[i];
        in.radius = state_.radius[i];
        const SpinClock spin{state_.spin(i), time(), 0.0};
        in.spin = &spin;
        f.load(in);
        return f(state_.position(i), state_.velocity(i), time()).a;
    });
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

}  // namespace pl
