// The broad phase's pairs kept from step to step: each swept box is grown by a margin h into a
// "fat box", the grid (broad_phase.hpp) finds the pairs of fat boxes, and while every swept box
// stays inside its fat box those pairs hold every pair of overlapping swept boxes: a step then
// only tests their exact boxes. Verlet's neighbour list with a skin (L. Verlet, Phys. Rev. 159,
// 98, 1967); the fat AABBs of Box2D's and Bullet's dynamic trees.
//
// When a few boxes leave their fat boxes (a particle struck in a collision, a user's drag), their
// pairs are mended instead: each gets a new fat box, its old fat pairs are dropped and its new
// ones found through the last run's grid (and among the boxes mended since, which the grid holds
// stale). The grid is run again when too many left (the `most_*` limits below), when the particles that take part change, or
// when a particle that slept at the last run wakes (the grid leaves out pairs of two sleepers).
// The result is always the set of overlapping pairs the grid alone would give, sorted: the cache
// changes the cost, never the pairs, on any number of threads.
//
// Each particle's margin is `steps_ahead` times its own farthest move along an axis in the step
// (`SweptBoxes::move`): a particle on a straight path stays inside for that many steps, a slow one
// gets a thin fat box, a fast one a wide one (a uniform margin sized by the fastest particle made
// every fat box as wide as the fastest one's). It is capped at a quarter of the free space
// between boxes (the mean spacing (V/m)^(1/3) less the median box) and at twice the box's own
// longest side, so the fat boxes of a dilute gas meet few others, a crowd's fat boxes a bounded
// number.
// Fat boxes are not made for the next `quiet_calls` calls when they served only the call that
// made them (some ball of a settling pile always leaves), or when they made more than one fat
// pair per box (a crowd: testing those each step costs about what the grid does). A settling pile
// runs the plain grid, a sleeping one none.
#pragma once

#include "physics/collide/broad_phase.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace pl::collide {

class PairCache {
public:
    // Half a step past a whole number: a particle on a straight path stays inside its fat box for
    // the 6 steps after the grid run and is then clearly out (on a whole number it would end on
    // the boundary, where round-off decides). On the gas at 1e5 (dt 1 and 2 ms) 6.5 cost less
    // than 3, 3.5 and 4.5.
    static constexpr double steps_ahead = 6.5;
    // Mended rather than run again: at most this share of the boxes leaving in one call, and of
    // the boxes mended since the grid ran.
    static constexpr double most_leavers_share = 1.0 / 16.0;
    static constexpr double most_mended_share = 1.0 / 8.0;
    // ... and at most this many box tests per box of the leavers against the mended ones (each
    // leaver tests every box mended since the run: a grid run costs some tens of tests a box).
    static constexpr double most_mend_tests_per_box = 4.0;
    static constexpr std::uint64_t quiet_calls = 16;       // calls without a margin after one wasted
    static constexpr double most_fat_pairs_per_box = 1.0;  // more: a crowd, no margin (the gas: 0.3)

    // Replaces `pairs` by every overlapping pair of `boxes.ids` (with `asleep`, not two sleeping
    // ones), sorted: what BroadPhase::find_pairs gives.
    void find_pairs(const SweptBoxes& boxes, std::vector<Pair>& pairs, const std::uint8_t* asleep = nullptr,
                    std::size_t threads = 1);

    // The same for a caller that makes the boxes itself (CollisionPass::build_boxes): the test of
    // each box against its fat box is done as the box is made, while it is in cache, instead of
    // in a pass of its own over all boxes. Before making them, watch(tasks, n) (n: the particle
    // indices); when it returns true, check(task, i, box, asleep) every box of `ids` once, each
    // task over a range of indices in increasing order, the ranges in task order. Then
    // find_pairs_watched, with `ids_same` false when `ids` may differ from the last call's.
    bool watch(std::size_t tasks, std::size_t particles);
    void check(std::size_t task, std::uint32_t i, const SweptBox& b, bool asleep) {
        const SweptBox& f = fat_.box[i];
        TaskWatch& watch = task_watch_[task];
        if (slept_[i] && !asleep) watch.holds = false;  // woke: the grid left out its pairs with sleepers
        if (!contains(f, b)) watch.leavers.push_back(i);
    }
    void find_pairs_watched(const SweptBoxes& boxes, std::vector<Pair>& pairs, const std::uint8_t* asleep,
                            std::size_t threads, bool ids_same);

    // After a call: appends to `out` every particle of the call whose swept box may meet `box`
    // (a superset: the grid's boxes of the call, or its fat boxes and the ones mended since,
    // each containing the particle's swept box; each particle may come more than once) and
    // returns true; or false, appending nothing, when the grid cannot answer (a box spanning
    // too many of its cells). The collision pass pairs a struck particle's new path with it.
    bool near(const SweptBox& box, std::vector<std::uint32_t>& out) const;

    const BroadPhase& grid() const { return grid_; }
    double margin() const { return margin_; }                       // the largest, of the last grid run
    std::size_t fat_pair_count() const { return fat_pairs_.size(); }  // pairs of fat boxes
    std::uint64_t calls() const { return calls_; }
    std::uint64_t grid_runs() const { return grid_runs_; }
    std::uint64_t mends() const { return mends_; }  // calls that mended the fat pairs

private:
    bool find_leavers(const SweptBoxes& boxes, const std::uint8_t* asleep, std::size_t threads);
    void begin_checks(std::size_t tasks);  // the per-task state check() fills
    bool join_leavers();
    void pairs_after_leavers(bool holds, const SweptBoxes& boxes, std::vector<Pair>& pairs, const std::uint8_t* asleep,
                             std::size_t threads);
    bool mend(const SweptBoxes& boxes);
    double choose_cap(const SweptBoxes& boxes, std::size_t threads);
    double margin_of(const SweptBoxes& boxes, std::uint32_t i) const;
    static SweptBox fat_box(const SweptBoxes& boxes, std::uint32_t i, double margin);
    void forget_mended();
    void grow_boxes(const SweptBoxes& boxes, const std::uint8_t* asleep, std::size_t threads);
    void test_fat_pairs(const SweptBoxes& boxes, std::vector<Pair>& pairs, const std::uint8_t* asleep,
                        std::size_t threads);

    BroadPhase grid_;
    SweptBoxes fat_;                   // the fat boxes, per particle index; ids as at the last run
    std::vector<std::uint8_t> slept_;  // per particle index: asleep at the last run
    std::vector<Pair> fat_pairs_;      // overlapping pairs of fat boxes, sorted
    std::vector<std::vector<Pair>> slice_pairs_;
    // One task's part of the watch, on cache lines of its own: the tasks write theirs at once
    // (side by side, every push to one task's leavers moved the line under the other's).
    struct alignas(64) TaskWatch {
        std::vector<std::uint32_t> leavers;
        bool holds = true;
    };
    std::vector<TaskWatch> task_watch_;
    std::vector<double> task_margin_;
    std::vector<std::uint32_t> leavers_;  // boxes out of their fat boxes, this call, by index
    // Mending: the boxes mended since the grid ran (their entries in the grid are stale), a flag
    // per particle index for them and for this call's leavers, the particles a leaver's query
    // met (a stamp per particle index against repeats), the new fat boxes and pairs.
    std::vector<std::uint32_t> mended_, near_, stamp_;
    std::vector<std::uint8_t> is_mended_, is_leaver_;
    std::vector<SweptBox> new_fat_;
    std::vector<Pair> new_pairs_, kept_pairs_;
    std::uint32_t query_ = 0;
    BoxSpreadScratch spread_scratch_;
    double cap_ = 0.0;     // the margins' cap at the last grid run (0: no margins)
    double margin_ = 0.0;  // the largest margin at the last grid run
    bool valid_ = false;
    bool watched_ = false;  // check() ran since watch()
    bool ran_grid_ = false;  // the last call ran the grid (else its fat pairs served)
    std::uint64_t calls_ = 0, grid_runs_ = 0, mends_ = 0;
    std::uint64_t served_ = 0;       // calls the fat boxes served (with the one that made them)
    std::uint64_t quiet_until_ = 0;  // no margin before this call
};

}  // namespace pl::collide
