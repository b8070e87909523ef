#include "physics/collide/pair_cache.hpp"

#include "physics/collide/slices.hpp"

#include <algorithm>
#include <cmath>

namespace pl::collide {

bool PairCache::find_leavers(const SweptBoxes& boxes, const std::uint8_t* asleep, std::size_t threads) {
    // False when the fat boxes cannot serve at all (other particles take part, or one woke);
    // else leavers_ lists the boxes out of their fat boxes (each task's in index order, joined in
    // task order). The ids are compared on the threads, as the boxes are read.
    if (!valid_ || boxes.ids.size() != fat_.ids.size() || boxes.box.size() != fat_.box.size()) return false;
    const std::size_t m = boxes.ids.size();
    begin_checks(range_tasks(m, threads));
    for_ranges(m, threads, [&](std::size_t begin, std::size_t end, std::size_t task) {
        for (std::size_t n = begin; n < end && task_watch_[task].holds; ++n) {
            const std::uint32_t i = boxes.ids[n];
            if (i != fat_.ids[n]) task_watch_[task].holds = false;
            else check(task, i, boxes.box[i], asleep && asleep[i]);
        }
    });
    return join_leavers();
}

bool PairCache::join_leavers() {
    leavers_.clear();
    for (const TaskWatch& watch : task_watch_) {
        if (!watch.holds) return false;
        leavers_.insert(leavers_.end(), watch.leavers.begin(), watch.leavers.end());
    }
    return true;
}

void PairCache::begin_checks(std::size_t tasks) {
    task_watch_.resize(tasks);
    for (TaskWatch& watch : task_watch_) {
        watch.leavers.clear();
        watch.holds = true;
    }
}

bool PairCache::watch(std::size_t tasks, std::size_t particles) {
    watched_ = valid_ && fat_.box.size() == particles;
    if (watched_) begin_checks(tasks);
    return watched_;
}

double PairCache::choose_cap(const SweptBoxes& boxes, std::size_t threads) {
    // A quarter of the free space between the boxes: the mean spacing (the boxes' region over
    // their number, cube root) less the median box. 0 when nothing moves.
    if (!(boxes.reach > 0.0)) return 0.0;
    const BoxSpread spread = spread_of(boxes, threads, spread_scratch_);
    double volume = 1.0;
    for (int k = 0; k < 3; ++k) volume *= spread.high[k] - spread.low[k];
    const double spacing = std::cbrt(volume / static_cast<double>(boxes.ids.size()));
    return std::max(0.0, 0.25 * (spacing - spread.median));  // 0 if not finite
}

double PairCache::margin_of(const SweptBoxes& boxes, std::uint32_t i) const {
    // Its own move steps_ahead times over, at most the cap and twice its box's longest side (a
    // crowd's fat boxes are at most five boxes wide, whatever one fast ball far away does; at
    // once the box, the fast balls of the gas at dt = 2 ms left early: a grid run in 4 steps
    // instead of 6).
    return std::min({cap_, steps_ahead * static_cast<double>(boxes.move[i]), 2.0 * boxes.extent(i)});
}

SweptBox PairCache::fat_box(const SweptBoxes& boxes, std::uint32_t i, double margin) {
    SweptBox f;
    for (int k = 0; k < 3; ++k) {
        f.lo[k] = boxes.box[i].lo[k] - margin;
        f.hi[k] = boxes.box[i].hi[k] + margin;
    }
    return f;
}

void PairCache::grow_boxes(const SweptBoxes& boxes, const std::uint8_t* asleep, std::size_t threads) {
    fat_.box.resize(boxes.box.size());
    fat_.ids = boxes.ids;
    slept_.assign(boxes.box.size(), 0);
    task_margin_.assign(range_tasks(boxes.ids.size(), threads), 0.0);
    for_ranges(boxes.ids.size(), threads, [&](std::size_t begin, std::size_t end, std::size_t task) {
        double largest = 0.0;
        for (std::size_t n = begin; n < end; ++n) {
            const std::uint32_t i = boxes.ids[n];
            const double margin = margin_of(boxes, i);
            fat_.box[i] = fat_box(boxes, i, margin);
            largest = std::max(largest, margin);
            slept_[i] = asleep ? asleep[i] : 0;
        }
        task_margin_[task] = largest;
    });
    margin_ = *std::max_element(task_margin_.begin(), task_margin_.end());
}

bool PairCache::mend(const SweptBoxes& boxes) {
    // The leavers' new fat boxes, and their fat pairs: with the boxes of the last grid run that
    // have not moved since (through the grid), with the boxes mended since (which the grid holds
    // stale) and with each other. Nothing changes unless every leaver's query succeeds. Leavers
    // are awake: a sleeping particle is held where it slept.
    const double m = static_cast<double>(boxes.ids.size()), leavers = static_cast<double>(leavers_.size());
    const double mended = static_cast<double>(mended_.size());
    if (leavers > most_leavers_share * m || mended + leavers > most_mended_share * m ||
        leavers * (mended + leavers) > most_mend_tests_per_box * m)
        return false;
    for (const std::uint32_t i : leavers_) is_leaver_[i] = 1;
    new_fat_.clear();
    new_pairs_.clear();
    bool found = true;
    for (std::size_t l = 0; found && l < leavers_.size(); ++l) {
        const std::uint32_t i = leavers_[l];
        const SweptBox f = fat_box(boxes, i, margin_of(boxes, i));
        new_fat_.push_back(f);
        near_.clear();
        found = grid_.near(f, near_);
        if (++query_ == 0) {  // the stamps wrapped around
            std::fill(stamp_.begin(), stamp_.end(), 0u);
            query_ = 1;
        }
        auto meet = [&](std::uint32_t j, const SweptBox& g) {
            if (overlap(f, g)) new_pairs_.push_back({std::min(i, j), std::max(i, j)});
        };
        for (const std::uint32_t j : near_) {  // stale: the mended ones and the leavers
            if (j == i || is_mended_[j] || is_leaver_[j] || stamp_[j] == query_) continue;
            stamp_[j] = query_;
            meet(j, fat_.box[j]);
        }
        for (const std::uint32_t j : mended_)
            if (!is_leaver_[j]) meet(j, fat_.box[j]);
        for (std::size_t k = 0; k < l; ++k) meet(leavers_[k], new_fat_[k]);
    }
    if (found) {
        for (std::size_t l = 0; l < leavers_.size(); ++l) {
            const std::uint32_t i = leavers_[l];
            fat_.box[i] = new_fat_[l];
            if (!is_mended_[i]) mended_.push_back(i);
            is_mended_[i] = 1;
        }
        kept_pairs_.clear();
        for (const Pair& p : fat_pairs_)
            if (!is_leaver_[p.a] && !is_leaver_[p.b]) kept_pairs_.push_back(p);
        std::sort(new_pairs_.begin(), new_pairs_.end());
        fat_pairs_.resize(kept_pairs_.size() + new_pairs_.size());
        std::merge(kept_pairs_.begin(), kept_pairs_.end(), new_pairs_.begin(), new_pairs_.end(), fat_pairs_.begin());
        ++mends_;
    }
    for (const std::uint32_t i : leavers_) is_leaver_[i] = 0;
    return found;
}

bool PairCache::near(const SweptBox& box, std::vector<std::uint32_t>& out) const {
    // A grid run this call holds every particle's box of the call (swept, or fat around it). Fat
    // pairs that served hold the last run's fat boxes, stale for the boxes mended since: those
    // are looked at one by one (at most most_mended_share of the particles; a few hundred on
    // the gas between its grid runs).
    if (calls_ == 0 || !grid_.near(box, out)) return false;
    if (!ran_grid_)
        for (const std::uint32_t j : mended_)
            if (overlap(box, fat_.box[j])) out.push_back(j);
    return true;
}

void PairCache::forget_mended() {
    for (const std::uint32_t i : mended_) is_mended_[i] = 0;
    mended_.clear();
    is_mended_.resize(fat_.box.size(), 0);
    is_leaver_.resize(fat_.box.size(), 0);
    stamp_.resize(fat_.box.size(), 0);
}

void PairCache::test_fat_pairs(const SweptBoxes& boxes, std::vector<Pair>& pairs, const std::uint8_t* asleep,
                               std::size_t threads) {
    // In slices of the sorted fat pairs, joined in order: sorted, on any number of threads.
    append_in_slices(fat_pairs_.size(), threads, 16384, slice_pairs_, pairs,
                     [&](std::size_t begin, std::size_t end, std::vector<Pair>& out) {
                         constexpr std::size_t ahead = 8;  // the b's are out of memory order
                         for (std::size_t n = begin; n < end; ++n) {
                             if (n + ahead < end) __builtin_prefetch(&boxes.box[fat_pairs_[n + ahead].b]);
                             const Pair p = fat_pairs_[n];
                             if (asleep && asleep[p.a] && asleep[p.b]) continue;
                             if (boxes.overlap(p.a, p.b)) out.push_back(p);
                         }
                     });
}

void PairCache::find_pairs(const SweptBoxes& boxes, std::vector<Pair>& pairs, const std::uint8_t* asleep,
                           std::size_t threads) {
    pairs_after_leavers(find_leavers(boxes, asleep, threads), boxes, pairs, asleep, threads);
}

void PairCache::find_pairs_watched(const SweptBoxes& boxes, std::vector<Pair>& pairs, const std::uint8_t* asleep,
                                   std::size_t threads, bool ids_same) {
    const bool holds = watched_ && ids_same && boxes.ids.size() == fat_.ids.size() && join_leavers();
    watched_ = false;
    pairs_after_leavers(holds, boxes, pairs, asleep, threads);
}

void PairCache::pairs_after_leavers(bool holds, const SweptBoxes& boxes, std::vector<Pair>& pairs,
                                    const std::uint8_t* asleep, std::size_t threads) {
    // `holds`: the fat boxes can serve, and leavers_ lists the boxes out of them.
    ++calls_;
    pairs.clear();
    ran_grid_ = false;
    if (holds && (leavers_.empty() || (margin_ > 0.0 && mend(boxes)))) {
        ++served_;
        return test_fat_pairs(boxes, pairs, asleep, threads);
    }
    ran_grid_ = true;
    // Fat boxes that served only the call that made them cost more than they saved (a settling
    // pile: some ball always leaves): no margin for a while.
    if (margin_ > 0.0 && served_ < 2) quiet_until_ = calls_ + quiet_calls;
    served_ = 1;
    ++grid_runs_;
    cap_ = calls_ < quiet_until_ || boxes.ids.size() < 2 ? 0.0 : choose_cap(boxes, threads);
    if (cap_ == 0.0 && boxes.reach > 0.0) {  // no margin, and boxes move: nothing worth keeping
        valid_ = false;
        margin_ = 0.0;
        return grid_.find_pairs(boxes, pairs, asleep, threads);
    }
    grow_boxes(boxes, asleep, threads);
    forget_mended();
    // With a margin the fat pairs need not be exact (each call tests the exact boxes).
    grid_.find_pairs(fat_, fat_pairs_, asleep, threads, margin_ == 0.0);
    valid_ = true;
    // A crowd (a pile): a fat pair or more per box, and testing them each step costs about what
    // the grid does: no margin for a while.
    if (margin_ > 0.0 && static_cast<double>(fat_pairs_.size()) > most_fat_pairs_per_box * static_cast<double>(boxes.ids.size()))
        quiet_until_ = calls_ + quiet_calls;
    if (margin_ > 0.0) return test_fat_pairs(boxes, pairs, asleep, threads);
    pairs = fat_pairs_;  // still boxes, no margin: these are the pairs
}

}  // namespace pl::collide
