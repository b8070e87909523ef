// Sleeping islands: particles at rest in a pile stop being stepped until something touches them.
//
// An island is a connected set of particles under the pair contacts of the contact solver (walls
// do not join islands: they do not move). A particle in some pair contact is still while its
// speed and its surface speed of spin stay below the contact's rest speed; an island falls asleep
// when all its particles have been still for time_to_sleep (Box2D's rule and its 0.5 s,
// b2_timeToSleep). Asleep, a particle keeps the position it had and no velocity, so a pile that
// has settled cannot creep. A particle that touches an island (a new contact) joins it with a
// still time of zero, and the whole island wakes at the end of that step.
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

    // After a step of length h: updates each particle's still time from its velocity and spin
    // and decides who sleeps during the next step. `rest_speed` <= 0: nothing sleeps.
    void update(const ParticleState& s, const std::vector<SolverContact>& contacts, double rest_speed, double h);
    // Wakes particle i's island at the next update (an outside change, e.g. a velocity set by hand).
    void wake(std::uint32_t i);

    const std::vector<std::uint8_t>& asleep() const { return asleep_; }
    std::size_t asleep_count() const { return asleep_count_; }

private:
    std::uint32_t root(std::uint32_t i);

    std::vector<double> still_;           // s each particle has been still in contact
    std::vector<std::uint32_t> parent_;   // union-find over this step's contacts
    std::vector<double> island_still_;    // per root: the least still time of its particles
    std::vector<std::uint8_t> in_contact_;
    std::vector<std::uint8_t> asleep_;
    std::vector<std::uint32_t> members_;  // particles in some pair contact this step
    std::size_t asleep_count_ = 0;
};

}  // namespace pl::collide
