// The broad phase's pairs put in order (BroadPhase, broad_phase.hpp): the scan finds them cell by
// cell, in slices, and every caller takes them sorted by (a, b).
#include "physics/collide/broad_phase.hpp"

#include <algorithm>
#include <span>

namespace pl::collide {

bool BroadPhase::by_count(std::size_t pairs) const {
    // A counting sort's histogram has a bin per particle index: worth it unless the pairs are
    // much fewer than the particles.
    return 8 * pairs >= boxes_->box.size();
}

void BroadPhase::count_sort(std::span<const std::vector<Pair>> sources, std::vector<Pair>& pairs) {
    // By a counting sort on a (one pass over the pairs, stable), then each run of one a put in
    // order of b by insertion (a particle has a few pairs at most: the runs are short). The
    // comparison sort of the slices and their merge took a third of the gas's grid run.
    first_pair_of_.assign(boxes_->box.size() + 1, 0);
    std::size_t total = 0;
    for (const std::vector<Pair>& source : sources) {
        total += source.size();
        for (const Pair& p : source) ++first_pair_of_[p.a + 1];
    }
    for (std::size_t i = 1; i < first_pair_of_.size(); ++i) first_pair_of_[i] += first_pair_of_[i - 1];
    pairs.resize(total);
    for (const std::vector<Pair>& source : sources)
        for (const Pair& p : source) pairs[first_pair_of_[p.a]++] = p;
    for (std::size_t k = 1; k < total; ++k) {
        const Pair p = pairs[k];
        std::size_t j = k;
        for (; j > 0 && p < pairs[j - 1]; --j) pairs[j] = pairs[j - 1];
        pairs[j] = p;
    }
}

void BroadPhase::merge_slices(std::vector<Pair>& pairs) {
    // The sorted slices merged two by two (log2 of the slices passes over the pairs, instead of
    // sorting them all on one thread).
    run_end_.clear();
    pairs.clear();
    for (const std::vector<Pair>& slice : slice_pairs_) {
        pairs.insert(pairs.end(), slice.begin(), slice.end());
        run_end_.push_back(pairs.size());
    }
    while (run_end_.size() > 1) {
        merged_.resize(pairs.size());
        std::size_t begin = 0, kept = 0;
        for (std::size_t r = 0; r < run_end_.size(); r += 2) {
            const std::size_t middle = run_end_[r], end = r + 1 < run_end_.size() ? run_end_[r + 1] : middle;
            std::merge(pairs.begin() + static_cast<std::ptrdiff_t>(begin), pairs.begin() + static_cast<std::ptrdiff_t>(middle),
                       pairs.begin() + static_cast<std::ptrdiff_t>(middle), pairs.begin() + static_cast<std::ptrdiff_t>(end),
                       merged_.begin() + static_cast<std::ptrdiff_t>(begin));
            run_end_[kept++] = end;
            begin = end;
        }
        run_end_.resize(kept);
        pairs.swap(merged_);
    }
}

}  // namespace pl::collide
