// The registry of force terms, and the one place a kernel is built from the terms a scene
// enables. Each group lists alternatives (at most one of a group is enabled, the first whose
// enabled(model) holds); a kernel is instantiated for every combination of the groups, and the
// scene's combination is picked at run time, once, when the simulation is built.
// A new term is a header in this folder and one line in TermGroups.
#pragma once

#include "physics/model/forces.hpp"
#include "physics/model/terms/air_column.hpp"
#include "physics/model/terms/buoyancy.hpp"
#include "physics/model/terms/drag_linear.hpp"
#include "physics/model/terms/drag_quadratic.hpp"
#include "physics/model/terms/drag_sphere_re.hpp"
#include "physics/model/terms/gravity.hpp"
#include "physics/model/terms/magnus.hpp"
#include "physics/model/terms/wind.hpp"

#include <tuple>
#include <type_traits>

namespace pl::terms {

template <class... Alternatives>
struct Group {};

// Gravity is always on and comes first; then the groups, in this order. The flight groups are
// the terms of a point mass in uniform air (the fast kernel's); the spin group needs the
// particle's spin, and the air column reloads the others per evaluation, which only the generic
// kernel does (scene.hpp: needs_generic_kernel).
using FlightTermGroups = std::tuple<Group<DragLinear, DragQuadratic, DragSphereRe>,  //
                                    Group<Wind>,                                     //
                                    Group<Buoyancy>>;
using TermGroups = decltype(std::tuple_cat(FlightTermGroups{}, std::tuple<Group<Magnus>, Group<AirColumn>>{}));

namespace detail {

// Whether term T can join the terms chosen so far (an air term only acts through a drag).
template <class T, class... Chosen>
constexpr bool fits = T::role != TermRole::air || ((Chosen::role == TermRole::drag) || ...);

template <class Groups, std::size_t G, class Fn, class... Chosen>
auto build(const Model& m, Fn&& fn);

// Tries group G's alternatives A, Rest... in order; none enabled: the group adds nothing.
template <class Groups, std::size_t G, class Fn, class... Chosen, class A, class... Rest>
auto choose(const Model& m, Fn&& fn, Group<A, Rest...>) {
    if constexpr (fits<A, Chosen...>) {
        if (A::enabled(m)) return build<Groups, G + 1, Fn, Chosen..., A>(m, static_cast<Fn&&>(fn));
    }
    if constexpr (sizeof...(Rest) > 0) {
        return choose<Groups, G, Fn, Chosen...>(m, static_cast<Fn&&>(fn), Group<Rest...>{});
    } else {
        return build<Groups, G + 1, Fn, Chosen...>(m, static_cast<Fn&&>(fn));
    }
}

template <class Groups, std::size_t G, class Fn, class... Chosen>
auto build(const Model& m, Fn&& fn) {
    if constexpr (G == std::tuple_size_v<Groups>) {
        return fn.template operator()<Forces<Chosen...>>();
    } else {
        return choose<Groups, G, Fn, Chosen...>(m, static_cast<Fn&&>(fn), std::tuple_element_t<G, Groups>{});
    }
}

}  // namespace detail

// fn.template operator()<F>() with F = Forces<the terms the model enables among Groups>; its result.
template <class Groups = TermGroups, class Fn>
auto with_enabled_terms(const Model& m, Fn&& fn) {
    return detail::build<Groups, 0, Fn, Gravity>(m, static_cast<Fn&&>(fn));
}

}  // namespace pl::terms
