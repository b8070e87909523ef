// Sleeping islands: particles at rest in a pile stop being stepped until something touches them.
//
// An island is a connected set of particles under the pair contacts of the contact solver (walls
// do not join islands: they do not move; a particle resting on a wall and touching no other is an
// island of its own). A particle in some pair contact is still while its
// speed and its surface speed of spin stay below the contact's rest speed; an island falls asleep
// when all its particles have been still for time_to_sleep (Box2D's rule and its 0.5 s,
// b2_timeToSleep). Asleep, a particle keeps the position it had and no velocity, so a pile that
// has settled cannot creep, and the pairs of two sleeping particles are not even looked for. The
// island is remembered (a ring of its particles): when an awake particle touches one of them, or
// one is struck or kicked, the whole island wakes at the end of that step.
#pragma once

#include "physics/collide/contact_solver.hpp"
#include "physics/stepping/particle_state.hpp"

#include <cstdint>
#include <vector>

namespace pl::collide {

class SleepIslands {
public:
    static constexpr double time_to_sleep = 0.5;  // s

    explicit SleepIslands(std::size_t particles);

    // After a step of length h, once the islands touched, struck or kicked have been woken
    // (wake): updates each awake particle's still time from its velocity and spin, and puts to
    // sleep the islands still long enough. `rest_speed` <= 0: nothing sleeps. The pass over the
    // particles runs on up to `threads` threads (the same result on any number).
    void update(const ParticleState& s, const std::vector<SolverContact>& contacts, double rest_speed, double h,
                std::size_t threads = 1);
    // Wakes particle i's island now (its velocity was set from outside, or it was struck).
    void wake(std::uint32_t i);

    const std::vector<std::uint8_t>& asleep() const { return asleep_; }
    // The particles in pair contacts whose islands fell asleep in the last update (in island
    // order; not those alone on a wall, whose rest is the wall's).
    const std::vector<std::uint32_t>& fell_asleep() const { return fell_asleep_; }
    std::size_t asleep_count() const { return asleep_count_; }

private:
    std::uint32_t root(std::uint32_t i);
    void update_still(const ParticleState& s, double rest_speed, double h, std::size_t threads);
    void wake_island(std::uint32_t i);
    void fall_asleep(const std::vector<std::uint32_t>& members);

    std::vector<double> still_;           // s each particle has been still in contact
    std::vector<std::uint32_t> parent_;   // union-find over this step's contacts
    std::vector<double> island_still_;    // per root: the least still time of its particles
    std::vector<std::uint8_t> in_contact_;  // this step: 0, in_pair or alone_on_wall
    static constexpr std::uint8_t in_pair = 1, alone_on_wall = 2;
    std::vector<std::uint8_t> asleep_;
    std::vector<std::uint32_t> ring_;     // asleep: the next particle of its island (a ring)
    std::vector<std::uint32_t> members_;  // awake particles in some pair contact this step
    static constexpr std::uint32_t none = 0xffffffffu;
    std::vector<std::uint32_t> head_, next_member_;  // per root: its island's particles, chained
    std::vector<std::uint32_t> island_;   // scratch: one island's particles
    std::vector<std::uint32_t> fell_asleep_;
    std::vector<std::vector<std::uint32_t>> task_resting_;  // per task: particles alone on a wall
    std::size_t asleep_count_ = 0;
};

}  // namespace pl::collide
