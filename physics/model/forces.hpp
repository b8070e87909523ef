// The force sum, assembled at compile time from the list of terms a scene enables
// (terms/term_list.hpp builds the list; terms/*.hpp hold the terms): a term that is off is not
// in the list, so it costs nothing and is never evaluated (the counters prove it).
// Everything is per unit mass: accelerations and powers in W/kg.
#pragma once

#include "physics/model/terms/term.hpp"

#include <glm/geometric.hpp>

#include <cstdint>
#include <type_traits>

namespace pl {

// Time derivative of the flight state: acceleration plus the two ledger rates.
struct Derivative {
    Vec3 a{0.0};
    double drag_power = 0.0;  // energy dissipated by drag (relative to the air), >= 0
    double wind_power = 0.0;  // work done on the particle by the air (wind through drag, body terms of the air)
};

// Linear-drag view of the forces at one state, for the exponential integrator:
// a = body - k (v - w) with k, w and the constant body accelerations frozen over the step.
struct LinearisedForces {
    double k = 0.0;
    Vec3 wind{0.0};
    Vec3 body{0.0};   // gravity plus the other body terms
    Vec3 extra{0.0};  // the body terms other than gravity (their work goes to the air_work line)
    // The air column's m / M (terms/air_column.hpp): k and body are per kg of the inertial mass
    // M, extra per kg of m (the ledger's unit), so the drag's ledger uses k / inertia_scale.
    double inertia_scale = 1.0;
};

namespace detail {
template <TermRole R, class... Terms>
struct first_with_role {
    using type = void;
};
template <TermRole R, class T, class... Rest>
struct first_with_role<R, T, Rest...> {
    using type = std::conditional_t<T::role == R, T, typename first_with_role<R, Rest...>::type>;
};
}  // namespace detail

// A Forces functor's terms reloaded for the air at height y (terms/air_column.hpp), counting
// their evaluations in the original (the copy's counters start at 0 and are added back as it
// is destroyed).
template <class F>
struct LocalAir {
    const F& origin;
    F local;
    LocalAir(const F& f, double y) : origin(f), local(f) {
        local.load(static_cast<const typename F::AirColumnTerm&>(f).inputs_at(y));
        local.clear_evaluations();
    }
    LocalAir(const LocalAir&) = delete;
    LocalAir& operator=(const LocalAir&) = delete;
    ~LocalAir() { origin.take_evaluations(local); }
    const F* operator->() const { return &local; }
};

// Terms: the gravity term first, then at most one drag term, at most one air term, and body
// terms (constant forces per particle), in terms/term_list.hpp's order.
template <class... Terms>
struct Forces : Terms... {
    using DragTerm = typename detail::first_with_role<TermRole::drag, Terms...>::type;
    using AirTerm = typename detail::first_with_role<TermRole::air, Terms...>::type;
    using LiftTerm = typename detail::first_with_role<TermRole::lift, Terms...>::type;
    using AirColumnTerm = typename detail::first_with_role<TermRole::medium, Terms...>::type;
    static constexpr bool has_air_column = !std::is_void_v<AirColumnTerm>;
    static constexpr bool has_drag = !std::is_void_v<DragTerm>;
    static constexpr bool has_wind = !std::is_void_v<AirTerm>;
    static constexpr bool has_lift = !std::is_void_v<LiftTerm>;
    // Forces besides gravity and drag (the exponential step freezes them over the step).
    static constexpr bool has_extra_body = ((Terms::role == TermRole::body) || ...) || has_lift;
    // Which ledger lines the enabled terms write (a line nobody writes is left untouched).
    static constexpr bool writes_drag = ((Terms::ledger == Ledger::drag) || ...);
    static constexpr bool writes_air_work = ((Terms::ledger == Ledger::air_work) || ...);
    // Whether the forces on a particle at rest are the same for every particle (see term.hpp).
    static constexpr bool rest_is_uniform = (Terms::rest_is_uniform && ...);

    void load(const TermInputs& in) { (Terms::load(in), ...); }

    // The wind field the air term looks up (null without one, or with the wind known ahead).
    const WindField* wind_field() const {
        if constexpr (has_wind) {
            if constexpr (requires(const AirTerm& a) { a.wind; }) return AirTerm::wind;
        }
        return nullptr;
    }

    double drag_rate(const Vec3& u) const {
        if constexpr (has_drag) return DragTerm::rate(u);
        else return 0.0;
    }

    Vec3 air_velocity(const Vec3& x, double t) const {
        if constexpr (has_wind) return AirTerm::at(x, t);
        else return Vec3(0.0);
    }

    // The derivative at (x, v, t): the terms' sum, through the air column where there is one.
    Derivative operator()(const Vec3& x, const Vec3& v, double t) const {
        if constexpr (has_air_column) {
            const typename AirColumnTerm::Here here = AirColumnTerm::at(x.y);
            Derivative d = AirColumnTerm::varies ? in_air_at(x.y)->in_uniform_air(x, v, t) : in_uniform_air(x, v, t);
            d.a = AirColumnTerm::inertial(here, d.a, v);  // the powers stay per kg of m
            return d;
        } else {
            return in_uniform_air(x, v, t);
        }
    }

    // The linear-drag view (integrators.hpp: exponential_step), through the air column likewise.
    LinearisedForces linearise(const Vec3& x, const Vec3& v, double t) const {
        if constexpr (has_air_column) {
            const typename AirColumnTerm::Here here = AirColumnTerm::at(x.y);
            LinearisedForces l = AirColumnTerm::varies ? in_air_at(x.y)->linearised_in_uniform_air(x, v, t)
                                                       : linearised_in_uniform_air(x, v, t);
            l.k *= here.scale;
            l.body = AirColumnTerm::inertial(here, l.body, v);
            l.inertia_scale = here.scale;
            return l;
        } else {
            return linearised_in_uniform_air(x, v, t);
        }
    }

    Derivative in_uniform_air(const Vec3& x, const Vec3& v, double t) const {
        ++this->gravity_term().evals;
        Derivative d{this->gravity};
        if constexpr (has_drag) {
            ++DragTerm::evals;
            const Vec3 w = air_velocity(x, t);
            const Vec3 u = v - w;
            const double c = drag_rate(u);
            const Vec3 a_drag = -c * u;
            d.a += a_drag;
            d.drag_power = drag_power(c, u);
            if constexpr (has_wind) d.wind_power = AirTerm::power(a_drag, w);
            add_lift(d, u, v, t);
        } else {
            add_lift(d, v, v, t);
        }
        (add_body<Terms>(d, v), ...);
        return d;
    }

    LinearisedForces linearised_in_uniform_air(const Vec3& x, const Vec3& v, double t) const {
        ++this->gravity_term().evals;
        LinearisedForces l;
        l.body = this->gravity;
        if constexpr (has_drag) {
            ++DragTerm::evals;
            l.wind = air_velocity(x, t);
            l.k = drag_rate(v - l.wind);
        }
        if constexpr (has_lift) {
            Derivative lift;
            add_lift(lift, v - l.wind, v, t);
            l.body += lift.a;
            l.extra += lift.a;
        }
        (add_body<Terms>(l), ...);
        return l;
    }

    // The evaluations counted so far, each in its term's slot.
    ForceCounters evaluations() const {
        ForceCounters c;
        ((c.*Terms::counter += Terms::evals), ...);
        return c;
    }
    void clear_evaluations() { ((Terms::evals = 0), ...); }
    // Adds the evaluations another copy counted.
    void take_evaluations(const Forces& other) const { ((Terms::evals += other.Terms::evals), ...); }
    // Adds `times` the evaluations `per` counts (as if the lanes had evaluated through this functor).
    void add_evaluations(const ForceCounters& per, std::uint64_t times) {
        ((Terms::evals += times * (per.*Terms::counter)), ...);
    }

private:
    LocalAir<Forces> in_air_at(double y) const { return LocalAir<Forces>(*this, y); }

    using GravityTerm = typename detail::first_with_role<TermRole::gravity, Terms...>::type;
    const GravityTerm& gravity_term() const { return *this; }

    // The lift at air-relative velocity u (normal to u: its work dot(a, v) is done by the air).
    void add_lift([[maybe_unused]] Derivative& d, [[maybe_unused]] const Vec3& u, [[maybe_unused]] const Vec3& v,
                  [[maybe_unused]] double t) const {
        if constexpr (has_lift) {
            ++LiftTerm::evals;
            const Vec3 a = LiftTerm::lift(u, t);
            d.a += a;
            d.wind_power += glm::dot(a, v);
        }
    }

    // Body terms other than gravity, after the drag: their acceleration and their work.
    template <class T>
    void add_body(Derivative& d, const Vec3& v) const {
        if constexpr (T::role == TermRole::body) {
            ++T::evals;
            const Vec3 a = T::acceleration(this->gravity);
            d.a += a;
            d.wind_power += T::power(a, v);
        }
    }
    template <class T>
    void add_body(LinearisedForces& l) const {
        if constexpr (T::role == TermRole::body) {
            ++T::evals;
            const Vec3 a = T::acceleration(this->gravity);
            l.body += a;
            l.extra += a;
        }
    }
};

}  // namespace pl
