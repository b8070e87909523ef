// Shock propagation (ContactSolver, contact_solver.hpp): a last pass over the resting contacts of a
// scene whose contacts join very unequal masses, from the lowest up, in which the lower ball of
// each contact counts as immovable (Guendelman, Bridson & Fedkiw, "Nonconvex rigid bodies with
// stacking", SIGGRAPH 2003, sec. 7; Erleben, "Velocity-based shock propagation for multibody
// dynamics animation", ACM TOG 26(2), 2007).
//
// Why: sequential impulses are a Gauss-Seidel iteration, and a heavy ball on a light one
// converges at a rate set by their mass ratio. A light ball between the floor and a heavy ball
// takes a small share of each impulse the heavy one needs: at 1 : 1000 ten iterations (and warm
// starting over many steps) hold back a fraction of the heavy ball's weight, and a column of
// alternating masses sank into its light balls by a quarter of their radius. In one pass from the
// floor up, with each lower ball fixed, every ball is held by what is under it whatever the masses.
//
// The pass only pushes (each contact's normal impulse grows, never shrinks), only along contacts
// that carry weight (their normal at least `shock_least_rise` from the horizontal), and books its
// impulses in the contacts' accumulated ones (the next step's warm start gives the lower balls
// their reaction). It runs on one thread in a fixed order (the same bits on any number of
// threads), and only in a scene that needs it: contacts whose masses differ by more than
// `shock_mass_ratio`. Below it the iterations alone hold a column of eight alternating masses
// under 1% of a radius (0.8% at 1 : 49), and equal balls keep their bits.
#include "physics/collide/contact_solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pl::collide {

bool ContactSolver::needs_shock(const Model& m) const {
    if (!(glm::length(m.world.gravity) > 0.0)) return false;  // nothing carries a weight
    // The bodies' masses first (found as they were loaded): a pile of equal balls stops here.
    double least = std::numeric_limits<double>::infinity(), most = 0.0;
    for (const auto& [task_least, task_most] : task_masses_) {
        least = std::min(least, task_least);
        most = std::max(most, task_most);
    }
    if (!(most > shock_mass_ratio * least)) return false;
    for (const SolverContact& c : coloured_) {
        if (c.is_wall()) continue;
        const double ma = body_[c.body_a].mass, mb = body_[c.body_b].mass;
        if (std::max(ma, mb) > shock_mass_ratio * std::min(ma, mb)) return true;
    }
    return false;
}

void ContactSolver::propagate_shock(const ParticleState& s, const Model& m) {
    const Vec3 up = -glm::normalize(m.world.gravity);
    // The contacts that carry weight, by the height of their lower ball (then their place: a
    // fixed order).
    order_bottom_up(
        s, up, coloured_,
        [&](const SolverContact& c) { return !c.is_wall() && carries_weight(c.n, up, 1.0, shock_least_rise); },
        shock_order_);
    for (const auto& [height, k] : shock_order_) {
        SolverContact& c = coloured_[k];
        // n runs from a to b: b is the upper ball when n rises.
        const bool b_upper = glm::dot(c.n, up) > 0.0;
        Body& upper = body_[b_upper ? c.body_b : c.body_a];
        const Body& lower = body_[b_upper ? c.body_a : c.body_b];
        // The normal relative velocity (b's minus a's): a sphere's spin adds nothing along n.
        const double un = glm::dot(b_upper ? upper.v - lower.v : lower.v - upper.v, c.n);
        if (!(un < c.least_un)) continue;
        const double impulse = upper.mass * (c.least_un - un);  // > 0, on the upper ball alone
        upper.v += (b_upper ? impulse : -impulse) / upper.mass * c.n;
        c.lambda_n += impulse;
    }
}

}  // namespace pl::collide
