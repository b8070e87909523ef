// The broad phase's pairs kept from step to step: each swept box is grown by a margin h into a
// "fat box", the grid (broad_phase.hpp) finds the pairs of fat boxes, and while every swept box
// stays inside its fat box those pairs hold every pair of overlapping swept boxes: a step then
// only tests their exact boxes. Verlet's neighbour list with a skin (L. Verlet, Phys. Rev. 159,
// 98, 1967); the fat AABBs of Box2D's and Bullet's dynamic trees.
//
// The grid is run again when a box leaves its fat box, when the particles that take part change,
// or when a particle that slept at the last run wakes (the grid leaves out pairs of two
// sleepers). The result is always the set of overlapping pairs the grid alone would give, sorted:
// the cache changes the cost, never the pairs, on any number of threads.
//
// The margin is `steps_ahead` (3) times the farthest a box moved in the step (`SweptBoxes::reach`):
// the fastest particle stays inside for about that many steps. It is capped at a quarter of the
// free space between boxes (the mean spacing (V/m)^(1/3) less the median box) and at half the
// median box, so the fat boxes of a dilute gas meet few others, a crowd's fat boxes a bounded
// number. Fat boxes are not made for the next `quiet_calls` calls when they served only the call
// that made them (some ball of a settling pile always leaves), or when they made more than one
// fat pair per box (a crowd: testing those each step costs about what the grid does). A settling
// pile runs the plain grid, a sleeping one none.
#pragma once

#include "physics/collide/broad_phase.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace pl::collide {

class PairCache {
public:
    // The fat boxes cost the grid more the larger they are (more entries and pairs per box): on
    // the gas at 1e5, 2 to 4 steps ahead cost least (1 to 16 measured at dt 1 and 2 ms).
    static constexpr double steps_ahead = 3.0;
    static constexpr std::uint64_t quiet_calls = 16;       // calls without a margin after one wasted
    static constexpr double most_fat_pairs_per_box = 1.0;  // more: a crowd, no margin (the gas: 0.3)

    // Replaces `pairs` by every overlapping pair of `boxes.ids` (with `asleep`, not two sleeping
    // ones), sorted: what BroadPhase::find_pairs gives.
    void find_pairs(const SweptBoxes& boxes, std::vector<Pair>& pairs, const std::uint8_t* asleep = nullptr,
                    std::size_t threads = 1);
    void forget() { valid_ = false; }  // the next call runs the grid

    const BroadPhase& grid() const { return grid_; }
    double margin() const { return margin_; }                       // of the last grid run
    std::size_t fat_pair_count() const { return fat_pairs_.size(); }  // pairs of fat boxes
    std::uint64_t calls() const { return calls_; }
    std::uint64_t grid_runs() const { return grid_runs_; }

private:
    bool still_holds(const SweptBoxes& boxes, const std::uint8_t* asleep, std::size_t threads);
    double choose_margin(const SweptBoxes& boxes);
    void grow_boxes(const SweptBoxes& boxes, const std::uint8_t* asleep, std::size_t threads);
    void test_fat_pairs(const SweptBoxes& boxes, std::vector<Pair>& pairs, const std::uint8_t* asleep,
                        std::size_t threads);

    BroadPhase grid_;
    SweptBoxes fat_;                   // the fat boxes, per particle index; ids as at the last run
    std::vector<std::uint8_t> slept_;  // per particle index: asleep at the last run
    std::vector<Pair> fat_pairs_;      // overlapping pairs of fat boxes, sorted
    std::vector<std::vector<Pair>> slice_pairs_;
    std::vector<std::uint8_t> task_holds_;
    std::vector<double> sample_;
    double margin_ = 0.0;
    bool valid_ = false;
    std::uint64_t calls_ = 0, grid_runs_ = 0;
    std::uint64_t served_ = 0;       // calls the fat boxes served (with the one that made them)
    std::uint64_t quiet_until_ = 0;  // no margin before this call
};

}  // namespace pl::collide
