#include "physics/collide/broad_phase.hpp"

#include "physics/stepping/thread_pool.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>

namespace pl::collide {

void SweptBoxes::resize(std::size_t n) {
    for (int k = 0; k < 3; ++k) {
        lo[k].resize(n);
        hi[k].resize(n);
    }
}

double SweptBoxes::extent(std::uint32_t i) const {
    return std::max({hi[0][i] - lo[0][i], hi[1][i] - lo[1][i], hi[2][i] - lo[2][i]});
}

std::size_t BroadPhase::bucket_of(std::int64_t ix, std::int64_t iy, std::int64_t iz) const {
    // Teschner et al. 2003 ("Optimized spatial hashing for collision detection of deformable
    // objects"): three large primes and xor; then SplitMix64's finaliser, since the table size is
    // a power of two and the low bits of the plain products repeat over neighbouring cells.
    std::uint64_t h = static_cast<std::uint64_t>(ix) * 73856093u ^ static_cast<std::uint64_t>(iy) * 19349663u ^
                      static_cast<std::uint64_t>(iz) * 83492791u;
    h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ull;
    h = (h ^ (h >> 27)) * 0x94d049bb133111ebull;
    h ^= h >> 31;
    return static_cast<std::size_t>(h & (bucket_start_.size() - 2));
}

BroadPhase::Cell BroadPhase::cell_of(const SweptBoxes& boxes, std::uint32_t i) const {
    const double inv = 1.0 / cell_;
    Cell c;
    for (int k = 0; k < 3; ++k) c[k] = static_cast<std::int64_t>(std::floor(0.5 * (boxes.lo[k][i] + boxes.hi[k][i]) * inv));
    return c;
}

void BroadPhase::build_grid(const SweptBoxes& boxes) {
    const std::size_t m = boxes.ids.size();
    extents_.resize(m);
    for (std::size_t k = 0; k < m; ++k) extents_[k] = boxes.extent(boxes.ids[k]);
    // The cell: the largest box, so that a box meets only the 27 cells around its own (a dense
    // pile of equal balls then finds about 30 candidates per ball, not the 250 of a cell twice
    // as large); but no more than twice the median box, so that a few big or fast balls among
    // many small ones go to the list tested against all instead of coarsening the grid.
    const double largest = *std::max_element(extents_.begin(), extents_.end());
    std::nth_element(extents_.begin(), extents_.begin() + static_cast<std::ptrdiff_t>(m / 2), extents_.end());
    cell_ = std::min(largest, 2.0 * extents_[m / 2]);  // > 0: every box holds a sphere of positive radius
    small_.clear();
    big_.clear();
    for (const std::uint32_t i : boxes.ids) (boxes.extent(i) <= cell_ ? small_ : big_).push_back(i);
    // Buckets: a power of two >= 2 m (few cells share one), plus the end marker.
    const std::size_t buckets = std::bit_ceil(std::max<std::size_t>(2 * small_.size(), 16));
    bucket_start_.assign(buckets + 1, 0);
    if (bucket_.size() < boxes.lo[0].size()) bucket_.resize(boxes.lo[0].size());
    if (cell_of_.size() < boxes.lo[0].size()) cell_of_.resize(boxes.lo[0].size());
    for (const std::uint32_t i : small_) {
        cell_of_[i] = cell_of(boxes, i);
        bucket_[i] = static_cast<std::uint32_t>(bucket_of(cell_of_[i][0], cell_of_[i][1], cell_of_[i][2]));
        ++bucket_start_[bucket_[i] + 1];
    }
    for (std::size_t b = 1; b <= buckets; ++b) bucket_start_[b] += bucket_start_[b - 1];
    sorted_.resize(small_.size());
    // Counting sort: each particle goes to the next free slot of its bucket (stable: ids order).
    next_.assign(bucket_start_.begin(), bucket_start_.end() - 1);
    for (const std::uint32_t i : small_) sorted_[next_[bucket_[i]]++] = i;
    slot_cell_.resize(sorted_.size());
    for (int k = 0; k < 3; ++k) {
        slot_lo_[k].resize(sorted_.size());
        slot_hi_[k].resize(sorted_.size());
    }
    for (std::size_t slot = 0; slot < sorted_.size(); ++slot) {
        const std::uint32_t i = sorted_[slot];
        slot_cell_[slot] = cell_of_[i];
        for (int k = 0; k < 3; ++k) {
            slot_lo_[k][slot] = boxes.lo[k][i];
            slot_hi_[k][slot] = boxes.hi[k][i];
        }
    }
}

void BroadPhase::scan_slots(std::size_t begin, std::size_t end, const std::uint8_t* asleep,
                            std::vector<Pair>& pairs) const {
    auto sleeps = [asleep](std::uint32_t i) { return asleep && asleep[i]; };
    // Slot by slot, so that consecutive particles share their neighbour buckets in cache. An awake
    // particle takes the pairs with higher awake ids and with every sleeping one (which does not
    // scan), so each pair is met once.
    for (std::size_t a = begin; a < end; ++a) {
        // A box no larger than a cell overlaps only boxes whose centres lie in the 27 cells around
        // its own centre's cell. Cells sharing a bucket are told apart by their coordinates, so
        // each neighbour is met once even when a bucket is scanned for two cells.
        const std::uint32_t i = sorted_[a];
        if (sleeps(i)) continue;
        const Cell c = slot_cell_[a];
        for (std::int64_t dx = -1; dx <= 1; ++dx)
            for (std::int64_t dy = -1; dy <= 1; ++dy)
                for (std::int64_t dz = -1; dz <= 1; ++dz) {
                    const Cell n{c[0] + dx, c[1] + dy, c[2] + dz};
                    const std::size_t b = bucket_of(n[0], n[1], n[2]);
                    for (std::uint32_t k = bucket_start_[b]; k < bucket_start_[b + 1]; ++k) {
                        const Cell& cj = slot_cell_[k];
                        const std::uint32_t j = sorted_[k];
                        if ((j > i || (j != i && sleeps(j))) && cj[0] == n[0] && cj[1] == n[1] && cj[2] == n[2] &&
                            slot_lo_[0][a] <= slot_hi_[0][k] && slot_lo_[0][k] <= slot_hi_[0][a] &&
                            slot_lo_[1][a] <= slot_hi_[1][k] && slot_lo_[1][k] <= slot_hi_[1][a] &&
                            slot_lo_[2][a] <= slot_hi_[2][k] && slot_lo_[2][k] <= slot_hi_[2][a])
                            pairs.push_back({std::min(i, j), std::max(i, j)});
                    }
                }
    }
}

void BroadPhase::find_pairs(const SweptBoxes& boxes, std::vector<Pair>& pairs, const std::uint8_t* asleep,
                            std::size_t threads) {
    pairs.clear();
    big_.clear();
    if (boxes.ids.size() < 2) return;
    build_grid(boxes);
    auto sleeps = [asleep](std::uint32_t i) { return asleep && asleep[i]; };
    // Below a few thousand particles a thread costs more to wake than its share saves.
    const std::size_t slices = threads > 1 && sorted_.size() >= 4096 ? 4 * threads : 1;
    if (slices == 1) {
        scan_slots(0, sorted_.size(), asleep, pairs);
    } else {
        slice_pairs_.resize(slices);
        auto task = [&](std::size_t k) {
            slice_pairs_[k].clear();
            scan_slots(sorted_.size() * k / slices, sorted_.size() * (k + 1) / slices, asleep, slice_pairs_[k]);
        };
        ThreadPool::shared().run(slices, threads, task);
        for (const std::vector<Pair>& slice : slice_pairs_) pairs.insert(pairs.end(), slice.begin(), slice.end());
    }
    // Big particles against all: a pair of two big ones is taken from the side that would take it
    // in the grid (the lower awake id, or the awake one).
    for (const std::uint32_t big : big_)
        for (const std::uint32_t j : boxes.ids) {
            if (j == big || (sleeps(big) && sleeps(j)) || !boxes.overlap(big, j)) continue;
            const bool other_big = boxes.extent(j) > cell_;
            if (other_big && (sleeps(big) || (!sleeps(j) && j < big))) continue;
            pairs.push_back({std::min(big, j), std::max(big, j)});
        }
    std::sort(pairs.begin(), pairs.end());
}

void all_pairs(const SweptBoxes& boxes, std::vector<Pair>& pairs) {
    pairs.clear();
    for (std::size_t p = 0; p < boxes.ids.size(); ++p)
        for (std::size_t q = p + 1; q < boxes.ids.size(); ++q)
            if (boxes.overlap(boxes.ids[p], boxes.ids[q])) pairs.push_back({boxes.ids[p], boxes.ids[q]});
}

}  // namespace pl::collide
