#include "physics/collide/sleep_islands.hpp"

#include <glm/geometric.hpp>

#include <algorithm>

namespace pl::collide {

SleepIslands::SleepIslands(std::size_t particles)
    : still_(particles, 0.0), parent_(particles), island_still_(particles, 0.0), in_contact_(particles, 0),
      asleep_(particles, 0) {
    for (std::uint32_t i = 0; i < particles; ++i) parent_[i] = i;
}

std::uint32_t SleepIslands::root(std::uint32_t i) {
    while (parent_[i] != i) {
        parent_[i] = parent_[parent_[i]];  // path halving
        i = parent_[i];
    }
    return i;
}

void SleepIslands::wake(std::uint32_t i) {
    still_[i] = 0.0;
    if (asleep_[i]) {
        asleep_[i] = 0;
        --asleep_count_;
    }
}

void SleepIslands::update(const ParticleState& s, const std::vector<SolverContact>& contacts, double rest_speed,
                          double h) {
    for (const std::uint32_t i : members_) {
        in_contact_[i] = 0;
        parent_[i] = i;
    }
    members_.clear();
    for (const SolverContact& c : contacts) {
        if (c.is_wall()) continue;
        for (const std::uint32_t i : {c.a, c.b})
            if (!in_contact_[i]) {
                in_contact_[i] = 1;
                members_.push_back(i);
            }
        const std::uint32_t ra = root(c.a), rb = root(c.b);
        if (ra != rb) parent_[std::max(ra, rb)] = std::min(ra, rb);  // the smaller index is the root: order-free
    }
    // Still time: a particle out of every pair contact, or moving, starts again from zero.
    for (std::uint32_t i = 0; i < s.size(); ++i) {
        if (!in_contact_[i]) {
            still_[i] = 0.0;
            continue;
        }
        const double surface = glm::length(s.spin(i)) * s.radius[i];
        const bool still = rest_speed > 0.0 && glm::length(s.velocity(i)) < rest_speed && surface < rest_speed;
        still_[i] = still ? still_[i] + h : 0.0;
    }
    for (const std::uint32_t i : members_) island_still_[root(i)] = still_[i];
    for (const std::uint32_t i : members_) {
        double& least = island_still_[root(i)];
        least = std::min(least, still_[i]);
    }
    asleep_count_ = 0;
    std::fill(asleep_.begin(), asleep_.end(), std::uint8_t{0});
    for (const std::uint32_t i : members_) {
        asleep_[i] = island_still_[root(i)] >= time_to_sleep;
        asleep_count_ += asleep_[i];
    }
}

}  // namespace pl::collide
