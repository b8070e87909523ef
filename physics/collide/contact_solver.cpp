#include "physics/collide/contact_solver.hpp"

#include "physics/collide/slices.hpp"
#include "physics/stepping/contact.hpp"

#include <glm/geometric.hpp>

#include "physics/stepping/thread_pool.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <iterator>
#include <limits>

namespace pl::collide {
namespace {

// The least normal relative velocity (<= 0, no push) a contact may end the step with. Position:
// the end gap after the solver's move (du times `push`, the method's share of h: scene.hpp,
// constant_push_share) stays >= 0, u_n' >= u_n - gap / push, where the pair ends the step apart
// or overlapping; but never a push apart (at most 0: overlaps are opened on positions). Explicit
// Euler's step does not move by the impulses (push = 0): no bound from the position then, unless
// the pair overlaps (no closing at all). Velocity: a contact closing slower than an impact may
// not close more than its gap over the next step, u_n' >= -max(gap, 0) / h (a faster one is an
// impact: the next step's).
double least_normal_velocity(double gap, double closing, double h, double push, double impact) {
    const double unbounded = -std::numeric_limits<double>::infinity();
    double least = push > 0.0 ? std::min(closing - gap / push, 0.0) : (gap < 0.0 ? 0.0 : unbounded);
    if (closing > -impact) least = std::max(least, -std::max(gap, 0.0) / h);
    return std::min(least, 0.0);
}

bool before(const SolverContact& x, const SolverContact& y) {
    if (x.a != y.a) return x.a < y.a;
    if (x.b != y.b) return x.b < y.b;
    return x.wall < y.wall;
}

double inverse_inertia(const ParticleState& s, std::uint32_t i) {
    return 1.0 / s.moment(i);
}

}  // namespace

bool ContactSolver::pair_contact(const ParticleState& s, const Model& m, const Pair& p,
                                 const std::vector<std::uint8_t>& asleep, double h, double impact, bool spin,
                                 SolverContact& c) {
    if (s.frozen[p.a] || s.frozen[p.b]) return false;
    const Vec3 d = s.position(p.b) - s.position(p.a);
    const double len = glm::length(d);
    if (!(len > 0.0)) return false;  // concentric: no normal (the overlap pass opens them first)
    const double reach = s.radius[p.a] + s.radius[p.b];
    const Vec3 n = d / len;
    const double closing = glm::dot(s.velocity(p.b) - s.velocity(p.a), n);
    const double gap = len - reach;
    if (gap > contact_margin * reach + std::max(-closing, 0.0) * h) return false;
    c = SolverContact{};
    c.a = p.a;
    c.b = p.b;
    c.n = n;
    c.least_un = least_normal_velocity(gap, closing, h, constant_push_share(m.integrator.method) * h, impact);
    // The inertial masses M move (added mass: the fluid too); the spin's moment is k m r^2.
    const double inv_a = 1.0 / s.inertial_mass[p.a], inv_b = 1.0 / s.inertial_mass[p.b];
    c.normal_mass = 1.0 / (inv_a + inv_b);
    c.tangent_mass = 1.0 / (inv_a + inv_b +
                            (spin ? 1.0 / (s.inertia[p.a] * s.mass[p.a]) + 1.0 / (s.inertia[p.b] * s.mass[p.b]) : 0.0));
    c.friction = m.collisions.friction;
    c.active = !(asleep[p.a] && asleep[p.b]);
    return true;
}

void ContactSolver::gather(const ParticleState& s, const Model& m, const std::vector<Pair>& pairs,
                           const std::vector<std::uint32_t>& struck, const std::vector<std::uint32_t>& caught,
                           const std::vector<std::uint8_t>& asleep, double h, double impact, std::size_t threads) {
    previous_.swap(contacts_);
    contacts_.clear();
    bodies_.clear();
    if (in_body_.size() < s.size()) in_body_.resize(s.size(), 0);
    const bool spin = spin_matters(m);
    auto add_body = [&](std::uint32_t i) {
        if (in_body_[i]) return;
        in_body_[i] = 1;
        bodies_.push_back(i);
    };
    // Threaded in slices of pairs, joined in order: the same contacts on any thread count.
    append_in_slices(pairs.size(), threads, 8192, slice_contacts_, contacts_,
                     [&](std::size_t begin, std::size_t end, std::vector<SolverContact>& out) {
                         SolverContact c;
                         for (std::size_t k = begin; k < end; ++k)
                             if (pair_contact(s, m, pairs[k], asleep, h, impact, spin, c)) out.push_back(c);
                     });
    for (const SolverContact& c : contacts_) {
        add_body(c.a);
        add_body(c.b);
    }
    // The walls under (and beside) the particles of the pair contacts and of this step's impacts:
    // the pile's weight, or a blow from above, has to reach the floor inside the same solve. A
    // particle touching no other is the kernel's alone. Made in the order of the bodies, so that
    // one merge puts them among the pair contacts (both lists in (a, b, wall) order).
    for (const std::uint32_t i : struck) add_body(i);
    sort_bodies(s.size());
    if (reach_.size() < s.size()) reach_.resize(s.size(), 0.0);
    reach_of_caught(s, caught, h);
    walls_.clear();
    append_in_slices(bodies_.size(), threads, 8192, slice_contacts_, walls_,
                     [&](std::size_t begin, std::size_t end, std::vector<SolverContact>& out) {
                         for (std::size_t k = begin; k < end; ++k) {
                             const std::uint32_t i = bodies_[k];
                             wall_contacts(s, m, i, asleep, h, impact, spin, reach_[i], out);
                         }
                     });
    for (const std::uint32_t i : caught) reach_[i] = 0.0;
    if (!walls_.empty()) {
        merged_.clear();
        std::merge(contacts_.begin(), contacts_.end(), walls_.begin(), walls_.end(), std::back_inserter(merged_), before);
        contacts_.swap(merged_);
    }
    keep_sleeping(asleep);
}

// The bodies in index order, their flags cleared. A settling pile's contacts hold most
// particles: a sweep of the flags then costs a byte a particle, where a sort of that many
// indices took 2% of its step on the serial thread. A few bodies among many particles (a gas)
// are sorted. The same list either way.
void ContactSolver::sort_bodies(std::size_t particles) {
    if (bodies_.size() * 16 >= particles) {
        bodies_.clear();
        for (std::uint32_t i = 0; i < particles; ++i)
            if (in_body_[i]) {
                bodies_.push_back(i);
                in_body_[i] = 0;
            }
        return;
    }
    std::sort(bodies_.begin(), bodies_.end());
    for (const std::uint32_t i : bodies_) in_body_[i] = 0;
}

void ContactSolver::wall_contacts(const ParticleState& s, const Model& m, std::uint32_t i,
                                  const std::vector<std::uint8_t>& asleep, double h, double impact, bool spin,
                                  double reach, std::vector<SolverContact>& out) {
    const RoomBounds room(m.room);
    const Vec3 v = s.velocity(i);
    for (int w = 0; w < wall_count; ++w) {
        const Vec3 inward = RoomBounds::inward_normal(w);
        const double gap = room.distance(w, s.position(i), s.radius[i]);
        const double closing = glm::dot(v, inward);  // the wall's velocity (0) minus the particle's, along n
        if (gap > contact_margin * s.radius[i] + std::max(-closing, 0.0) * h + reach) continue;
        SolverContact& c = out.emplace_back();
        c.a = i;
        c.b = SolverContact::wall_contact;
        c.wall = static_cast<std::uint8_t>(w);
        c.n = -inward;  // from the particle into the wall
        c.least_un = least_normal_velocity(gap, closing, h, constant_push_share(m.integrator.method) * h, impact);
        c.normal_mass = s.inertial_mass[i];
        c.tangent_mass = 1.0 / (1.0 / s.inertial_mass[i] + (spin ? 1.0 / (s.inertia[i] * s.mass[i]) : 0.0));
        c.friction = m.contact.friction;
        c.active = !asleep[i];
    }
}

void ContactSolver::keep_sleeping(const std::vector<std::uint8_t>& asleep) {
    // The contacts of sleeping islands are not looked for (the broad phase leaves their pairs
    // out): they are kept from the last step as they were, with their impulses, so that a pile
    // shows its contacts asleep and wakes with its weight already carried. Both lists are in
    // order: one merge.
    kept_.clear();
    for (const SolverContact& c : previous_)
        if (asleep[c.a] && (c.is_wall() || asleep[c.b])) {
            kept_.push_back(c);
            kept_.back().active = false;
        }
    if (kept_.empty()) return;
    merged_.clear();
    std::merge(contacts_.begin(), contacts_.end(), kept_.begin(), kept_.end(), std::back_inserter(merged_), before);
    contacts_.swap(merged_);
}

void ContactSolver::warm_start(std::size_t threads) {
    // Both lists are in (a, b, wall) order: a merge walk finds the contacts that persist, in
    // ranges of today's contacts on the threads, each from its first contact's place in the last
    // step's list (each range writes only its own contacts: the same bits).
    for_ranges(contacts_.size(), threads, [&](std::size_t begin, std::size_t end, std::size_t) {
        if (begin == end) return;
        auto prev = std::lower_bound(previous_.begin(), previous_.end(), contacts_[begin], before);
        for (std::size_t k = begin; k < end; ++k) {
            SolverContact& c = contacts_[k];
            while (prev != previous_.end() && before(*prev, c)) ++prev;
            if (prev == previous_.end()) break;
            if (before(c, *prev)) continue;
            c.lambda_n = prev->lambda_n;
            c.lambda_t = prev->lambda_t - glm::dot(prev->lambda_t, c.n) * c.n;  // onto today's tangent plane
        }
    });
}

void ContactSolver::place_bodies(const std::vector<std::uint32_t>& space_order) {
    // The bodies' slots in the order of space (the particles of `space_order` in its order, then
    // any it misses in index order): a contact's two bodies are neighbours in space, so with the
    // contacts taken in slot order (colour_contacts) the iterations read the bodies almost in
    // sequence. In index order, a pile of random indices read each body from main memory.
    // Bodies few among many particles (a gas, a pile mostly asleep) keep the index order: the
    // walk over `space_order` would cost more than their layout saves.
    slot_particle_.clear();
    if (bodies_.size() * few_bodies_share < space_order.size()) {
        slot_particle_ = bodies_;
        return;
    }
    for (const std::uint32_t i : bodies_) in_body_[i] = 1;
    for (const std::uint32_t i : space_order)
        if (i < in_body_.size() && in_body_[i] == 1) {
            in_body_[i] = 2;
            slot_particle_.push_back(i);
        }
    for (const std::uint32_t i : bodies_)
        if (in_body_[i] == 1) slot_particle_.push_back(i);
    for (const std::uint32_t i : bodies_) in_body_[i] = 0;
}

void ContactSolver::load_bodies(const ParticleState& s, const std::vector<std::uint32_t>& space_order,
                                std::size_t threads) {
    // Each body and each contact on its own (a particle has one slot): threaded, the same bits.
    place_bodies(space_order);
    if (slot_of_.size() < s.size()) slot_of_.resize(s.size());
    body_.resize(slot_particle_.size());
    v0_.resize(slot_particle_.size());
    w0_.resize(slot_particle_.size());
    // The least and largest mass of each task's bodies (shock propagation's first test).
    task_masses_.assign(range_tasks(slot_particle_.size(), threads), {0.0, 0.0});
    for_ranges(slot_particle_.size(), threads, [&](std::size_t begin, std::size_t end, std::size_t task) {
        double least = std::numeric_limits<double>::infinity(), most = 0.0;
        for (std::size_t k = begin; k < end; ++k) {
            const std::uint32_t i = slot_particle_[k];
            slot_of_[i] = static_cast<std::uint32_t>(k);
            body_[k] = {s.velocity(i), s.spin(i), s.inertial_mass[i], s.radius[i], inverse_inertia(s, i)};
            v0_[k] = body_[k].v;
            w0_[k] = body_[k].w;
            least = std::min(least, body_[k].mass);
            most = std::max(most, body_[k].mass);
        }
        task_masses_[task] = {least, most};
    });
    for_ranges(contacts_.size(), threads, [&](std::size_t begin, std::size_t end, std::size_t) {
        for (std::size_t k = begin; k < end; ++k) {
            SolverContact& c = contacts_[k];
            if (!c.active) continue;
            c.body_a = slot_of_[c.a];
            c.body_b = c.is_wall() ? 0 : slot_of_[c.b];
        }
    });
}

void ContactSolver::apply(const SolverContact& c, const Vec3& impulse, bool spin) {
    // `impulse` acts on b (along +n pushes b away from a); a takes its opposite, at the contact
    // point r_a n from its centre (b's is at -r_b n).
    Body& a = body_[c.body_a];
    a.v = a.v - impulse / a.mass;
    if (spin) a.w = a.w + glm::cross(a.radius * c.n, -impulse) * a.inverse_moment;
    if (c.is_wall()) return;
    Body& b = body_[c.body_b];
    b.v = b.v + impulse / b.mass;
    if (spin) b.w = b.w + glm::cross(-b.radius * c.n, impulse) * b.inverse_moment;
}

void ContactSolver::solve_contact(SolverContact& c, bool spin) {
    const Body& a = body_[c.body_a];
    const Body* b = c.is_wall() ? nullptr : &body_[c.body_b];
    auto relative_velocity = [&] {
        // Surface velocity of b minus a's at the contact point (a wall does not move).
        Vec3 u = -a.v;
        if (spin) u -= glm::cross(a.w, a.radius * c.n);
        if (b) {
            u += b->v;
            if (spin) u += glm::cross(b->w, -b->radius * c.n);
        }
        return u;
    };
    // Normal: u_n >= least_un, with lambda_n >= 0.
    const double un = glm::dot(relative_velocity(), c.n);
    const double lambda_n = std::max(c.lambda_n - c.normal_mass * (un - c.least_un), 0.0);
    apply(c, (lambda_n - c.lambda_n) * c.n, spin);
    c.lambda_n = lambda_n;
    // Friction: stop the sliding, within the Coulomb cone of today's normal impulse.
    if (!(c.friction > 0.0)) return;
    const Vec3 u = relative_velocity();
    const Vec3 ut = u - glm::dot(u, c.n) * c.n;
    Vec3 lambda_t = c.lambda_t - c.tangent_mass * ut;
    const double bound = c.friction * c.lambda_n, size = glm::length(lambda_t);
    if (size > bound) lambda_t *= bound / size;
    apply(c, lambda_t - c.lambda_t, spin);
    c.lambda_t = lambda_t;
}

void ContactSolver::colour_contacts() {
    // Greedy colouring in contact order: each active contact takes the first colour neither of
    // its particles has taken yet (a wall is no particle); past 63 colours, the shared colour.
    colours_of_body_.assign(body_.size(), 0);
    colour_of_.resize(contacts_.size());
    colour_start_.assign(shared_colour + 2, 0);
    for (std::size_t k = 0; k < contacts_.size(); ++k) {
        const SolverContact& c = contacts_[k];
        if (!c.active) continue;
        const std::uint64_t taken = colours_of_body_[c.body_a] | (c.is_wall() ? 0 : colours_of_body_[c.body_b]);
        const auto colour = static_cast<std::uint32_t>(std::min<int>(std::countr_one(taken), shared_colour));
        if (colour < shared_colour) {
            colours_of_body_[c.body_a] |= std::uint64_t{1} << colour;
            if (!c.is_wall()) colours_of_body_[c.body_b] |= std::uint64_t{1} << colour;
        }
        colour_of_[k] = static_cast<std::uint8_t>(colour);
        ++colour_start_[colour + 1];
    }
    for (std::size_t c = 1; c < colour_start_.size(); ++c) colour_start_[c] += colour_start_[c - 1];
}

void ContactSolver::order_by_colour(std::size_t threads) {
    // Each colour's contacts in the slot order of their first body (a counting sort by slot, then
    // a stable one by colour): a colour's contacts share no body, so their order changes no bit
    // of the result. The shared colour's do share bodies: they keep the contact order.
    auto lead = [](const SolverContact& c) { return c.is_wall() ? c.body_a : std::min(c.body_a, c.body_b); };
    slot_start_.assign(body_.size() + 1, 0);
    for (const SolverContact& c : contacts_)
        if (c.active) ++slot_start_[lead(c) + 1];
    for (std::size_t k = 1; k < slot_start_.size(); ++k) slot_start_[k] += slot_start_[k - 1];
    by_slot_.resize(slot_start_.back());
    for (std::uint32_t k = 0; k < contacts_.size(); ++k)
        if (contacts_[k].active) by_slot_[slot_start_[lead(contacts_[k])]++] = k;
    by_colour_.resize(colour_start_.back());
    next_in_colour_.assign(colour_start_.begin(), colour_start_.end() - 1);
    for (const std::uint32_t k : by_slot_)
        if (colour_of_[k] != shared_colour) by_colour_[next_in_colour_[colour_of_[k]]++] = k;
    for (std::uint32_t k = 0; k < contacts_.size(); ++k)
        if (contacts_[k].active && colour_of_[k] == shared_colour) by_colour_[next_in_colour_[shared_colour]++] = k;
    // The iterations read the contacts colour by colour: a copy in that order is one stream
    // through memory per colour, where the contacts in (a, b) order were a strided sweep of all
    // of them per colour (a pile of 1e5 holds 30 MB of contacts: every colour missed the caches).
    coloured_.resize(by_colour_.size());
    for_ranges(by_colour_.size(), threads, [&](std::size_t begin, std::size_t end, std::size_t) {
        for (std::size_t k = begin; k < end; ++k) coloured_[k] = contacts_[by_colour_[k]];
    });
}

template <class Visit>
void ContactSolver::for_each_coloured(std::size_t threads, Visit&& visit) {
    // Colour by colour; a large colour's contacts in slices on the threads (they share no
    // particle), the shared colour's one by one.
    for (std::uint32_t colour = 0; colour <= shared_colour; ++colour) {
        const std::uint32_t begin = colour_start_[colour], end = colour_start_[colour + 1];
        if (threads < 2 || colour == shared_colour || end - begin < parallel_colour) {
            for (std::uint32_t k = begin; k < end; ++k) visit(coloured_[k]);
            continue;
        }
        const std::size_t slices = 2 * threads;
        auto task = [&](std::size_t t) {
            const std::uint32_t from = begin + static_cast<std::uint32_t>((end - begin) * t / slices);
            const std::uint32_t to = begin + static_cast<std::uint32_t>((end - begin) * (t + 1) / slices);
            for (std::uint32_t k = from; k < to; ++k) visit(coloured_[k]);
        };
        ThreadPool::shared().run(slices, threads, task);
    }
}

std::uint64_t ContactSolver::solve(ParticleState& s, const Model& m, double h, const std::vector<Vec3>& start_velocity,
                                   const std::vector<Vec3>& start_spin, const std::vector<std::uint32_t>& space_order,
                                   std::size_t threads) {
    shocked_ = false;
    if (contacts_.empty()) return 0;
    const bool spin = spin_matters(m);
    load_bodies(s, space_order, threads);
    warm_start(threads);
    colour_contacts();
    order_by_colour(threads);
    for_each_coloured(threads, [&](const SolverContact& c) { apply(c, c.lambda_n * c.n + c.lambda_t, spin); });
    for (int it = 0; it < iterations; ++it) for_each_coloured(threads, [&](SolverContact& c) { solve_contact(c, spin); });
    clear_anchor_levels();
    shocked_ = needs_shock();
    if (shocked_) {
        propagate_shock(s, m);
        propagate_from_walls(s, m, h);
    }
    // The impulses back, for the next warm start (each contact once: threaded, the same bits),
    // and the loaded contacts counted (the sleeping ones keep theirs).
    task_loaded_.assign(range_tasks(contacts_.size(), threads), 0);
    for_ranges(by_colour_.size(), threads, [&](std::size_t begin, std::size_t end, std::size_t) {
        for (std::size_t k = begin; k < end; ++k) {
            contacts_[by_colour_[k]].lambda_n = coloured_[k].lambda_n;
            contacts_[by_colour_[k]].lambda_t = coloured_[k].lambda_t;
        }
    });
    for_ranges(contacts_.size(), threads, [&](std::size_t begin, std::size_t end, std::size_t task) {
        std::uint64_t count = 0;
        for (std::size_t k = begin; k < end; ++k) count += contacts_[k].lambda_n > 0.0;
        task_loaded_[task] = count;
    });
    std::uint64_t loaded = 0;
    for (const std::uint64_t count : task_loaded_) loaded += count;
    hand_back(s, m, h, start_velocity, start_spin, spin, threads);
    return loaded;
}

void ContactSolver::hand_back(ParticleState& s, const Model& m, double h, const std::vector<Vec3>& start_velocity,
                              const std::vector<Vec3>& start_spin, bool spin, std::size_t threads) {
    // The impulses acted over the whole step: the end positions move by dv times the method's
    // push (scene.hpp, constant_push_share: h for semi-implicit Euler, h / 2 for the methods
    // exact under a constant force, 0 for explicit Euler). Their work, booked from the
    // velocities (and spins) before the solve (vb) and after it (v1):
    //  - On the methods exact under a constant force: the change the solve makes to the ledger's
    //    energy, M dv . (vb + v1) / 2 - m g . dv h / 2 (kinetic and potential; spin's kinetic
    //    alike). The step then balances to its flight's own error, impacts (of walls and of
    //    pairs) included, and a contact holding a particle against gravity, buoyancy or wind
    //    books minus their work over the kernel's move, which it undoes.
    //  - On the Euler methods, which take the step's forces as kicks at its start: the impulse
    //    times the mean of the start's velocity (this step's pair impacts added: an impact's own
    //    work is booked where it is struck) and v1. With gravity's m g h (v0 + v1) / 2 that is
    //    semi-implicit Euler's change of kinetic energy.
    // Either way a contact at rest (v0 = v1 = 0) does no work: a still pile books nothing.
    const double push = constant_push_share(m.integrator.method) * h;
    const bool exact = exact_under_constant_force(m.integrator.method);
    const bool from_start = reads_start_velocities(s, m);  // !exact where work is booked
    // Each body writes only its own particle: threaded, the same bits.
    for_ranges(slot_particle_.size(), threads, [&](std::size_t begin, std::size_t end, std::size_t) {
        for (std::size_t k = begin; k < end; ++k) {
            const std::uint32_t i = slot_particle_[k];
            s.set_velocity(i, body_[k].v);
            s.set_spin(i, body_[k].w);
            const Vec3 dv = s.velocity(i) - v0_[k], dw = s.spin(i) - w0_[k];
            s.set_position(i, s.position(i) + push * dv);
            if (s.collision_work.empty()) continue;
            const double mi = s.inertial_mass[i], moment = s.moment(i);
            const Vec3 v_from = from_start ? start_velocity[i] : v0_[k];
            double work = mi * glm::dot(dv, 0.5 * (v_from + s.velocity(i)));
            if (exact) work -= s.mass[i] * glm::dot(m.world.gravity, push * dv);
            // Without spin dw = 0 and start_spin is not kept (the term is zero).
            if (spin) work += moment * glm::dot(dw, 0.5 * ((from_start ? start_spin[i] : w0_[k]) + s.spin(i)));
            s.collision_work[i] += work;
        }
    });
}

}  // namespace pl::collide
