// Resting contacts of particles among themselves and with the walls: the slow, lasting contacts
// of a pile, which impacts (resolved in time order by collision_pass.hpp) cannot hold still.
//
// Sequential impulses with accumulated, clamped impulses and warm starting (Catto, "Iterative
// Dynamics with Temporal Coherence", GDC 2005; "Fast and Simple Physics using Sequential
// Impulses", GDC 2006), the velocity solver of Box2D and Jolt, applied after the step: the
// impulses act over the whole step as a constant force would on the scene's method, so each
// particle's end position moves by its velocity change times h (semi-implicit Euler,
// x1 = x0 + v1 h) or h / 2 (the methods exact under a constant force). A contact's normal impulse
// lambda_n >= 0 keeps its normal relative velocity u_n at or above a least value: the end gap
// after that move is not negative, and a contact closing slower than an impact (collision_pass.hpp)
// does not close more than its gap over the next step. So a pile at rest stays touching, a pair
// that ends the step apart is never held back, and the solver gives no energy: no restitution
// (these contacts are slow) and no push apart in the velocities; overlaps left by round-off or
// by an emitter are opened on positions only (collision_pass.cpp). Friction is Coulomb's,
// |lambda_t| <= mu lambda_n, at the contact point (with spin where it matters).
//
// Warm starting applies last step's impulses of the contacts that persist (same pair or same
// particle and wall) before iterating: a pile's weight then reaches the floor over steps, not
// only over the iterations of one step.
//
// Threads: the contacts are coloured greedily so that no two of one colour share a particle
// (Box2D v3's constraint graph colouring), and each iteration solves the colours one after the
// other, a colour's contacts at once on the threads. The order (colour by colour, a fixed order
// within a colour) is the same on one thread, and contacts of one colour touch different
// particles: the same bits on any number of threads.
//
// Memory: the solver's bodies are laid out in an order of space (the broad phase's cells), and
// the iterations read a copy of the contacts grouped by colour, each colour's in the order of
// their bodies. A pile's particle indices are random in space: laid out by index, a pile of 1e5
// (contacts and bodies far beyond the caches) read each body and contact from main memory and
// solved 3x slower per ball than a pile of 1e4. The order within a colour changes no bit.
#pragma once

#include "physics/collide/broad_phase.hpp"
#include "physics/model/scene.hpp"
#include "physics/stepping/particle_state.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace pl::collide {

// A contact the solver holds: particles a and b (b = wall_contact for a contact of a with
// wall `wall`), the normal from a to b, its gap and its impulses.
struct SolverContact {
    static constexpr std::uint32_t wall_contact = 0xffffffffu;
    std::uint32_t a = 0, b = 0;
    std::uint8_t wall = 0;
    Vec3 n{0.0};
    double least_un = 0.0;   // m/s, the least normal relative velocity it may end with (<= 0)
    double normal_mass = 0;  // 1 / (1/M_a + 1/M_b), M the inertial mass (m, or m + added mass)
    double tangent_mass = 0; // 1 / K_t (with the spin's share where it matters)
    double friction = 0;
    double lambda_n = 0;     // accumulated normal impulse, N s (>= 0)
    Vec3 lambda_t{0.0};      // accumulated tangential impulse, N s
    bool active = true;      // false: both ends asleep; kept (with its impulses) but not solved
    std::uint32_t body_a = 0, body_b = 0;  // the solver's body slots of a and b (active contacts)
    bool is_wall() const { return b == wall_contact; }
};

// Shock propagation (contact_shock.cpp) and the overlap removal under it: whether a contact along
// d (of length `length`) carries weight, its slope's sine at least `least_rise` (side by side,
// nothing rests on the other); and the indices of `items` (each with particles a and b) that
// `keep` takes, from the lowest lower ball up along `up` (then by index).
inline bool carries_weight(const Vec3& d, const Vec3& up, double length, double least_rise) {
    return std::abs(glm::dot(d, up)) >= least_rise * length;
}
template <class Item, class Keep>
void order_bottom_up(const ParticleState& s, const Vec3& up, const std::vector<Item>& items, Keep&& keep,
                     std::vector<std::pair<double, std::uint32_t>>& order) {
    order.clear();
    for (std::uint32_t k = 0; k < items.size(); ++k)
        if (keep(items[k]))
            order.push_back({std::min(glm::dot(s.position(items[k].a), up), glm::dot(s.position(items[k].b), up)), k});
    std::sort(order.begin(), order.end());
}

class ContactSolver {
public:
    // Velocity iterations per step (Jolt's default is 10; Box2D v3 takes 4 substeps instead).
    static constexpr int iterations = 10;
    // Pairs whose surfaces are closer than this share of their contact distance at the end of
    // the step, or could close within the next, are contacts; walls likewise within this share
    // of the radius.
    static constexpr double contact_margin = 0.05;

    // Gathers the contacts among the candidate pairs (sorted) from the end state of the step in
    // s, and the wall contacts of their particles and of the `struck` ones (this step's
    // impacts); frozen particles take no part. A contact whose particles are all asleep is
    // listed (islands are made of contacts) but not solved. The `caught` particles (their
    // impacts reached the strike cap: a light ball between a heavy one and a wall) take the
    // walls within the distance their fastest closing contact covers in the step as contacts
    // too: the solver may push them that far.
    void gather(const ParticleState& s, const Model& m, const std::vector<Pair>& pairs,
                const std::vector<std::uint32_t>& struck, const std::vector<std::uint32_t>& caught,
                const std::vector<std::uint8_t>& asleep, double h, double impact, std::size_t threads = 1);
    // Solves them; changes the velocities (and spins) of s, and moves the end positions by the
    // velocity changes times the method's push (constant_push_share h). Adds the contacts' work
    // on each particle to s.collision_work, from the velocities and spins at the start of the
    // step with the step's impacts added (`start_velocity`, `start_spin`). Returns the number of contacts
    // that carry an impulse, sleeping ones included.
    // `space_order` lists particles in an order of space (the broad phase's cells; any order, or
    // none, gives the same result: it only lays the solver's bodies out in memory).
    std::uint64_t solve(ParticleState& s, const Model& m, double h, const std::vector<Vec3>& start_velocity,
                        const std::vector<Vec3>& start_spin, const std::vector<std::uint32_t>& space_order,
                        std::size_t threads = 1);
    // Whether solve reads `start_velocity` (and, with spin, `start_spin`): only to book the work
    // of a ledger on the Euler methods (hand_back); else they may hold anything.
    static bool reads_start_velocities(const ParticleState& s, const Model& m) {
        return !s.collision_work.empty() && !exact_under_constant_force(m.integrator.method);
    }

    const std::vector<SolverContact>& contacts() const { return contacts_; }
    // The last solve ended with shock propagation (contact_shock.cpp): its contacts join masses
    // more than shock_mass_ratio apart.
    bool propagated_shock() const { return shocked_; }

    // Shock propagation (contact_shock.cpp): the mass ratio past which it runs, and the least
    // sine of a normal's slope for a contact to carry weight (side by side, nothing rests on
    // the other).
    static constexpr double shock_mass_ratio = 50.0;
    static constexpr double shock_least_rise = 0.2;
    // The wall-anchored pass of shock propagation (contact_shock.cpp): a ball counts as held by a
    // wall (or by a ball held so) against a push whose direction is within this cosine of the
    // wall's normal (45 degrees); pushed more sideways, it slides.
    static constexpr double anchor_least_cosine = 0.7;
    static constexpr std::uint32_t unanchored = 0xffffffffu;
    // After a solve that propagated shock: how many balls particle i lies from a wall along a
    // chain of contacts that push it into that wall (0: it touches the wall; unanchored: no
    // such chain). The overlap removal holds the nearer ball of such a pair still.
    std::uint32_t anchor_level(std::uint32_t i) const { return i < anchor_level_.size() ? anchor_level_[i] : unanchored; }

private:
    // A particle as the iterations see it: its velocity and spin and what the impulses need, in
    // one place (Box2D's solver bodies), so that a contact reads two slots, not eighteen arrays.
    struct Body {
        Vec3 v, w;
        double mass, radius, inverse_moment;  // the inertial mass M; 1 / (k m r^2)
    };
    // The contact of a candidate pair, if its surfaces are close enough (false: none).
    static bool pair_contact(const ParticleState& s, const Model& m, const Pair& p, const std::vector<std::uint8_t>& asleep,
                             double h, double impact, bool spin, SolverContact& c);
    // The contacts of particle i with the walls it is close to, appended to `out` in wall order.
    // `reach`: how much farther than the contact margin a wall may be (caught particles).
    static void wall_contacts(const ParticleState& s, const Model& m, std::uint32_t i,
                              const std::vector<std::uint8_t>& asleep, double h, double impact, bool spin,
                              double reach, std::vector<SolverContact>& out);
    void reach_of_caught(const ParticleState& s, const std::vector<std::uint32_t>& caught, double h);
    void sort_bodies(std::size_t particles);  // bodies_ in index order, in_body_ cleared
    void keep_sleeping(const std::vector<std::uint8_t>& asleep);
    void warm_start(std::size_t threads);
    void place_bodies(const std::vector<std::uint32_t>& space_order);
    void load_bodies(const ParticleState& s, const std::vector<std::uint32_t>& space_order, std::size_t threads);
    void apply(const SolverContact& c, const Vec3& impulse, bool spin);
    void solve_contact(SolverContact& c, bool spin);
    // The solved velocities and spins back into s, the end positions moved, the work booked.
    void hand_back(ParticleState& s, const Model& m, double h, const std::vector<Vec3>& start_velocity,
                   const std::vector<Vec3>& start_spin, bool spin, std::size_t threads);
    void colour_contacts();
    void order_by_colour(std::size_t threads);
    // Shock propagation (contact_shock.cpp): whether the contacts join masses this unequal, and
    // the pass from the lowest contact up with each lower ball fixed.
    bool needs_shock() const;
    void propagate_shock(const ParticleState& s, const Model& m);
    // The pass from the walls out (contact_shock.cpp): the contacts the weight pass does not
    // take, each ball nearer a wall fixed; and whether slot x, pushed along p, is held.
    void propagate_from_walls(const ParticleState& s, const Model& m, double h);
    bool holds(std::uint32_t k) const { return held_[k] != 0; }  // coloured_[k] is a wall that holds its ball
    bool anchored(std::uint32_t x, const Vec3& p) const;
    void brace(std::uint32_t x, const Vec3& p);
    void clear_anchor_levels();
    template <class Visit>
    void for_each_coloured(std::size_t threads, Visit&& visit);

    std::vector<SolverContact> contacts_, previous_, kept_, merged_, walls_;
    std::vector<std::vector<SolverContact>> slice_contacts_;  // per slice of pairs, when threaded
    std::vector<std::uint32_t> bodies_;   // particles in some contact, increasing
    std::vector<std::uint8_t> in_body_;   // per particle: 0 outside gather and place_bodies
    std::vector<double> reach_;           // per particle: 0 but for the caught ones, in gather
    std::vector<std::uint8_t> is_caught_;  // per particle: 0 outside reach_of_caught
    std::vector<std::uint32_t> slot_particle_;  // per body slot: its particle (bodies in space order)
    std::vector<Vec3> v0_, w0_;           // velocity and spin of each body before the solve
    std::vector<Body> body_;              // per slot
    std::vector<std::uint32_t> slot_of_;  // per particle: its slot (valid for bodies only)
    // The colouring: the active contacts by colour (colour_start_[c] to colour_start_[c + 1] in
    // by_colour_; within a colour in the slot order of their lower body, by_slot_ ordering them
    // so), and per body slot the colours its contacts took.
    static constexpr std::uint32_t shared_colour = 63;  // the rest, which may share particles
    std::vector<std::uint64_t> colours_of_body_;
    std::vector<std::uint8_t> colour_of_;
    std::vector<std::uint32_t> colour_start_, by_colour_, next_in_colour_, slot_start_, by_slot_;
    std::vector<SolverContact> coloured_;  // the active contacts in by_colour_ order, while solving
    std::vector<std::uint64_t> task_loaded_;  // loaded contacts, per task of the count
    bool shocked_ = false;
    std::vector<std::pair<double, double>> task_masses_;  // least and largest body mass, per task of load_bodies
    std::vector<std::pair<double, std::uint32_t>> shock_order_;  // (height of the lower ball, coloured_ index)
    // The wall-anchored pass: per body slot its contacts (coloured_ indices, CSR), level and the
    // direction it is held along (unused for a ball on a wall: its wall contacts say), and the
    // slots in the order of their levels; per particle the levels of the last shocked solve
    // (anchored_ lists the particles written, to reset).
    std::vector<std::uint32_t> adjacency_start_, adjacency_, level_, by_level_, anchor_level_, anchored_;
    std::vector<Vec3> held_along_;
    std::vector<std::uint8_t> held_;  // per coloured_ contact: a wall its ball ends the step touching
    static constexpr std::uint32_t parallel_colour = 512;  // smaller colours run on one thread
    static constexpr std::size_t few_bodies_share = 4;     // bodies under 1/4 of the particles: index order
};

}  // namespace pl::collide
