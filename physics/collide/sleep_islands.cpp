#include "physics/collide/sleep_islands.hpp"

#include "physics/collide/slices.hpp"

#include <glm/geometric.hpp>

#include <algorithm>

namespace pl::collide {

SleepIslands::SleepIslands(std::size_t particles)
    : still_(particles, 0.0), parent_(particles), island_still_(particles, 0.0), in_contact_(particles, 0),
      asleep_(particles, 0), ring_(particles), head_(particles, none), next_member_(particles, none) {
    for (std::uint32_t i = 0; i < particles; ++i) parent_[i] = ring_[i] = i;
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
    wake_island(i);
}

void SleepIslands::wake_island(std::uint32_t i) {
    if (!asleep_[i]) return;
    std::uint32_t k = i;
    do {
        const std::uint32_t next = ring_[k];
        asleep_[k] = 0;
        ring_[k] = k;
        --asleep_count_;
        k = next;
    } while (k != i);
}

void SleepIslands::fall_asleep(const std::vector<std::uint32_t>& members) {
    for (std::size_t k = 0; k < members.size(); ++k) {
        asleep_[members[k]] = 1;
        ring_[members[k]] = members[(k + 1) % members.size()];
    }
    asleep_count_ += members.size();
    for (const std::uint32_t i : members)
        if (in_contact_[i] == in_pair) fell_asleep_.push_back(i);
}

void SleepIslands::update_still(const ParticleState& s, double rest_speed, double h, std::size_t threads) {
    // Still time: an awake particle out of every pair contact, or moving, starts again from zero.
    // A particle resting on a wall and touching no other is an island of its own (a member, in
    // index order after the contacts' members: each task's in order, joined in task order).
    task_resting_.resize(range_tasks(s.size(), threads));
    for_ranges(s.size(), threads, [&](std::size_t begin, std::size_t end, std::size_t task) {
        std::vector<std::uint32_t>& resting = task_resting_[task];
        resting.clear();
        for (std::size_t n = begin; n < end; ++n) {
            const auto i = static_cast<std::uint32_t>(n);
            if (asleep_[i]) continue;
            if (!in_contact_[i]) {
                if (!s.resting[i] || s.frozen[i]) {
                    still_[i] = 0.0;
                    continue;
                }
                in_contact_[i] = alone_on_wall;
                resting.push_back(i);
            }
            const double surface = glm::length(s.spin(i)) * s.radius[i];
            const bool still = rest_speed > 0.0 && glm::length(s.velocity(i)) < rest_speed && surface < rest_speed;
            still_[i] = still ? still_[i] + h : 0.0;
        }
    });
    for (const std::vector<std::uint32_t>& resting : task_resting_)
        members_.insert(members_.end(), resting.begin(), resting.end());
}

void SleepIslands::update(const ParticleState& s, const std::vector<SolverContact>& contacts, double rest_speed,
                          double h, std::size_t threads) {
    // (The islands touched by an awake particle, struck or kicked were woken before: wake().)
    fell_asleep_.clear();
    for (const std::uint32_t i : members_) {
        in_contact_[i] = 0;
        parent_[i] = i;
    }
    members_.clear();
    for (const SolverContact& c : contacts) {
        if (c.is_wall() || !c.active) continue;
        for (const std::uint32_t i : {c.a, c.b})
            if (!in_contact_[i]) {
                in_contact_[i] = in_pair;
                members_.push_back(i);
            }
        const std::uint32_t ra = root(c.a), rb = root(c.b);
        if (ra != rb) parent_[std::max(ra, rb)] = std::min(ra, rb);  // the smaller index is the root: order-free
    }
    update_still(s, rest_speed, h, threads);
    for (const std::uint32_t i : members_) island_still_[root(i)] = still_[i];
    for (const std::uint32_t i : members_) {
        double& least = island_still_[root(i)];
        least = std::min(least, still_[i]);
    }
    // Islands still long enough fall asleep. Each island's particles are chained from its root
    // (members_ is in contact order, so the rings are the same on every run).
    for (auto k = members_.rbegin(); k != members_.rend(); ++k) {
        const std::uint32_t r = root(*k);
        next_member_[*k] = head_[r];
        head_[r] = *k;
    }
    for (const std::uint32_t i : members_) {
        if (root(i) != i) continue;
        if (island_still_[i] >= time_to_sleep) {
            island_.clear();
            for (std::uint32_t k = head_[i]; k != none; k = next_member_[k]) island_.push_back(k);
            fall_asleep(island_);
        }
        head_[i] = none;
    }
}

}  // namespace pl::collide
