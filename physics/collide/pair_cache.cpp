#include "physics/collide/pair_cache.hpp"

#include "physics/collide/slices.hpp"

#include <algorithm>
#include <cmath>

namespace pl::collide {

bool PairCache::still_holds(const SweptBoxes& boxes, const std::uint8_t* asleep, std::size_t threads) {
    if (!valid_ || boxes.ids != fat_.ids || boxes.box.size() != fat_.box.size()) return false;
    const std::size_t m = boxes.ids.size();
    task_holds_.assign(range_tasks(m, threads), 1);
    for_ranges(m, threads, [&](std::size_t begin, std::size_t end, std::size_t task) {
        const SweptBox* box = boxes.box.data();
        const SweptBox* fat = fat_.box.data();
        for (std::size_t n = begin; n < end; ++n) {
            const std::uint32_t i = boxes.ids[n];
            const SweptBox &b = box[i], &f = fat[i];
            const bool inside = b.lo[0] >= f.lo[0] && b.lo[1] >= f.lo[1] && b.lo[2] >= f.lo[2] && b.hi[0] <= f.hi[0] &&
                                b.hi[1] <= f.hi[1] && b.hi[2] <= f.hi[2];
            const bool woke = slept_[i] && !(asleep && asleep[i]);
            if (!inside || woke) {
                task_holds_[task] = 0;
                return;
            }
        }
    });
    return std::all_of(task_holds_.begin(), task_holds_.end(), [](std::uint8_t h) { return h != 0; });
}

double PairCache::choose_margin(const SweptBoxes& boxes) {
    // steps_ahead times the farthest move of the step, at most a quarter of the free space
    // between the boxes (and half the median box, below): the mean spacing (the boxes' region over their number, cube root) less
    // the median box (from an evenly strided sample: the same on every run).
    if (!(boxes.reach > 0.0)) return 0.0;
    const std::size_t m = boxes.ids.size(), stride = std::max<std::size_t>(1, m / 1024);
    double low[3], high[3];
    for (int k = 0; k < 3; ++k) {
        low[k] = boxes.box[boxes.ids[0]].lo[k];
        high[k] = boxes.box[boxes.ids[0]].hi[k];
    }
    for (const std::uint32_t i : boxes.ids)
        for (int k = 0; k < 3; ++k) {
            low[k] = std::min(low[k], boxes.box[i].lo[k]);
            high[k] = std::max(high[k], boxes.box[i].hi[k]);
        }
    sample_.clear();
    for (std::size_t n = 0; n < m; n += stride) sample_.push_back(boxes.extent(boxes.ids[n]));
    const auto middle = sample_.begin() + static_cast<std::ptrdiff_t>(sample_.size() / 2);
    std::nth_element(sample_.begin(), middle, sample_.end());
    const double volume = (high[0] - low[0]) * (high[1] - low[1]) * (high[2] - low[2]);
    const double spacing = std::cbrt(volume / static_cast<double>(m));
    // Also at most half the median box: where most boxes crowd into a small part of the region
    // (a pile under one ball falling from a high ceiling) the mean spacing says nothing of them,
    // and fat boxes twice their size still meet a bounded number of neighbours each.
    const double cap = std::max(0.0, std::min(0.25 * (spacing - *middle), 0.5 * *middle));  // 0 if not finite
    return std::min(steps_ahead * boxes.reach, cap);
}

void PairCache::grow_boxes(const SweptBoxes& boxes, const std::uint8_t* asleep, std::size_t threads) {
    fat_.box.resize(boxes.box.size());
    fat_.ids = boxes.ids;
    slept_.assign(boxes.box.size(), 0);
    for_ranges(boxes.ids.size(), threads, [&](std::size_t begin, std::size_t end, std::size_t) {
        for (std::size_t n = begin; n < end; ++n) {
            const std::uint32_t i = boxes.ids[n];
            for (int k = 0; k < 3; ++k) {
                fat_.box[i].lo[k] = boxes.box[i].lo[k] - margin_;
                fat_.box[i].hi[k] = boxes.box[i].hi[k] + margin_;
            }
            slept_[i] = asleep ? asleep[i] : 0;
        }
    });
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
    ++calls_;
    pairs.clear();
    if (still_holds(boxes, asleep, threads)) {
        ++served_;
        return test_fat_pairs(boxes, pairs, asleep, threads);
    }
    // Fat boxes that served only the call that made them cost more than they saved (a settling
    // pile: some ball always leaves): no margin for a while.
    if (margin_ > 0.0 && served_ < 2) quiet_until_ = calls_ + quiet_calls;
    served_ = 1;
    ++grid_runs_;
    margin_ = calls_ < quiet_until_ || boxes.ids.size() < 2 ? 0.0 : choose_margin(boxes);
    if (margin_ == 0.0 && boxes.reach > 0.0) {  // no margin, and boxes move: nothing worth keeping
        valid_ = false;
        return grid_.find_pairs(boxes, pairs, asleep, threads);
    }
    grow_boxes(boxes, asleep, threads);
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
