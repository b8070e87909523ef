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
#include "physics/stepping/contact.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pl::collide {

bool ContactSolver::needs_shock() const {
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
    if (!(glm::length(m.world.gravity) > 0.0)) return;  // nothing carries a weight
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

// The pass from the walls out: a light ball between a wall and a heavy ball (a hammer on a nail
// against a wall) is the same Gauss-Seidel trap sideways, and with no gravity at all. The heavy
// ball's impacts end at the strike cap, the iterations take 1/1000 of its speed each, and alone
// they let it through the light ball. Here the balls are ordered by their distance from the walls
// along the contact graph (Guendelman et al. 2003, sec. 7, order the bodies by levels of the
// contact graph from the static ones; Erleben 2007, the same by a breadth-first search): a ball a
// wall holds (it ends the step touching it) is level 0; a ball whose push on a level-k ball that
// ball's wall, or chain of balls, holds is level k + 1. Then, level by level, each contact to the
// next level stops the outer ball closing on the inner one, the inner one fixed. Contacts the
// weight pass took are left to it.
bool ContactSolver::anchored(std::uint32_t x, const Vec3& p) const {
    if (level_[x] > 0) return glm::dot(p, held_along_[x]) >= anchor_least_cosine;
    for (std::uint32_t e = adjacency_start_[x]; e < adjacency_start_[x + 1]; ++e) {
        const SolverContact& c = coloured_[adjacency_[e]];
        if (holds(adjacency_[e]) && glm::dot(p, c.n) >= anchor_least_cosine) return true;  // n runs into the wall
    }
    return false;
}

void ContactSolver::brace(std::uint32_t x, const Vec3& p) {
    // A ball held by a wall, fixed from here on, does not move into it. (Its velocity may still
    // point in: the impacts' strike cap left it there, its end position clamped at the wall, and
    // its contact's least velocity allows what that position already took.) Only takes speed away.
    for (std::uint32_t e = adjacency_start_[x]; e < adjacency_start_[x + 1]; ++e) {
        const SolverContact& c = coloured_[adjacency_[e]];
        if (!holds(adjacency_[e]) || glm::dot(p, c.n) < anchor_least_cosine) continue;
        const double into = glm::dot(body_[x].v, c.n);  // n runs into the wall
        if (into > 0.0) body_[x].v -= into * c.n;
    }
}

void ContactSolver::propagate_from_walls(const ParticleState& s, const Model& m, double h) {
    // A wall holds a ball that ends the step touching it (its end position moved by the solve's
    // velocity change, as hand_back will move it): one within reach but not touched (a big ball
    // near a wall) holds nothing.
    const RoomBounds room(m.room);
    const double push = constant_push_share(m.integrator.method) * h;
    held_.assign(coloured_.size(), 0);
    for (std::uint32_t k = 0; k < coloured_.size(); ++k) {
        const SolverContact& c = coloured_[k];
        if (!c.is_wall()) continue;
        const double r = s.radius[c.a];
        const Vec3 end = s.position(c.a) + (body_[c.body_a].v - v0_[c.body_a]) * push;
        held_[k] = room.distance(c.wall, end, r) <= contact_margin * r;
    }
    const double g = glm::length(m.world.gravity);
    const Vec3 up = g > 0.0 ? -m.world.gravity / g : Vec3(0.0);
    auto taken = [&](const SolverContact& c) {  // by this pass: a ball contact the weight pass left
        return !c.is_wall() && !(g > 0.0 && carries_weight(c.n, up, 1.0, shock_least_rise));
    };
    // Each slot's contacts (the pass's and the walls'), in coloured_ order.
    const auto bodies = static_cast<std::uint32_t>(body_.size());
    adjacency_start_.assign(bodies + 2, 0);
    for (const SolverContact& c : coloured_) {
        if (!c.is_wall() && !taken(c)) continue;
        ++adjacency_start_[c.body_a + 2];
        if (!c.is_wall()) ++adjacency_start_[c.body_b + 2];
    }
    for (std::uint32_t k = 2; k < adjacency_start_.size(); ++k) adjacency_start_[k] += adjacency_start_[k - 1];
    adjacency_.resize(adjacency_start_.back());
    for (std::uint32_t k = 0; k < coloured_.size(); ++k) {
        const SolverContact& c = coloured_[k];
        if (!c.is_wall() && !taken(c)) continue;
        adjacency_[adjacency_start_[c.body_a + 1]++] = k;
        if (!c.is_wall()) adjacency_[adjacency_start_[c.body_b + 1]++] = k;
    }
    // The levels, breadth first from the balls on walls (in slot order: a fixed order).
    level_.assign(bodies, unanchored);
    held_along_.resize(bodies);
    by_level_.clear();
    for (std::uint32_t x = 0; x < bodies; ++x)
        for (std::uint32_t e = adjacency_start_[x]; e < adjacency_start_[x + 1]; ++e)
            if (holds(adjacency_[e])) {
                level_[x] = 0;
                by_level_.push_back(x);
                break;
            }
    for (std::size_t q = 0; q < by_level_.size(); ++q) {
        const std::uint32_t x = by_level_[q];
        for (std::uint32_t e = adjacency_start_[x]; e < adjacency_start_[x + 1]; ++e) {
            SolverContact& c = coloured_[adjacency_[e]];
            if (c.is_wall()) continue;
            const bool x_is_a = c.body_a == x;
            const std::uint32_t y = x_is_a ? c.body_b : c.body_a;
            if (level_[y] <= level_[x]) continue;
            const Vec3 n = x_is_a ? c.n : -c.n;  // from x to y: y pushes x along -n
            if (!anchored(x, -n)) continue;
            if (level_[x] == 0) brace(x, -n);
            if (level_[y] == unanchored) {
                level_[y] = level_[x] + 1;
                held_along_[y] = -n;
                by_level_.push_back(y);
            }
            // The contact solved once more with x fixed: y's normal velocity relative to x made
            // least_un, on y alone (a sphere's spin adds nothing along n). Closing faster, y
            // takes the push, which is not booked in the contact's accumulated impulse: it
            // stops a blow, not a lasting load, and the next step's warm start would replay it
            // on the light ball, which the iterations cannot take back. Moving away faster, y is
            // held back as far as the accumulated impulse (the iterations', of a warm start
            // that replayed last step's load) allows: the iterations could not take it back
            // through the light ball either, and the heavy ball left faster than it came.
            Body& outer = body_[y];
            const double un = glm::dot(outer.v - body_[x].v, n);
            const double change = un < c.least_un ? c.least_un - un : -std::min(un - c.least_un, c.lambda_n / outer.mass);
            outer.v += change * n;
            if (change < 0.0) c.lambda_n = std::max(c.lambda_n + outer.mass * change, 0.0);
        }
    }
    for (const std::uint32_t x : by_level_) {
        const std::uint32_t i = slot_particle_[x];
        if (anchor_level_.size() <= i) anchor_level_.resize(std::size_t{i} + 1, unanchored);
        anchor_level_[i] = level_[x];
        anchored_.push_back(i);
    }
}

void ContactSolver::reach_of_caught(const ParticleState& s, const std::vector<std::uint32_t>& caught, double h) {
    // A caught particle's reach (gather): its fastest closing pair contact's speed times the step.
    // The light ball between a wall and a heavy one reaches the strike cap, and may end the step
    // off the wall, bouncing back, while the solver will carry it into the wall with the heavy
    // ball: its wall has to be among the contacts for the pass from the walls. Rare (a step
    // whose impacts reached the cap), so one pass over the contacts.
    if (caught.empty()) return;
    if (is_caught_.size() < s.size()) is_caught_.resize(s.size(), 0);
    for (const std::uint32_t i : caught) is_caught_[i] = 1;
    for (const SolverContact& c : contacts_) {
        if (c.is_wall() || !(is_caught_[c.a] || is_caught_[c.b])) continue;
        const double closing = std::max(-glm::dot(s.velocity(c.b) - s.velocity(c.a), c.n), 0.0) * h;
        for (const std::uint32_t i : {c.a, c.b})
            if (is_caught_[i]) reach_[i] = std::max(reach_[i], closing);
    }
    for (const std::uint32_t i : caught) is_caught_[i] = 0;
}

void ContactSolver::clear_anchor_levels() {
    for (const std::uint32_t i : anchored_) anchor_level_[i] = unanchored;
    anchored_.clear();
}

}  // namespace pl::collide
