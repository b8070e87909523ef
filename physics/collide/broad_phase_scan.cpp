// The scan of the broad phase's sorted cell entries (BroadPhase, broad_phase.hpp): each cell's
// entries tested two by two, each pair reported by one cell, and the home cells' order of the
// particles made for the next call.
#include "physics/collide/broad_phase.hpp"

#include <algorithm>

namespace pl::collide {

std::size_t BroadPhase::scan_cells(std::size_t begin, std::size_t end, std::vector<Pair>& pairs,
                                   std::vector<std::uint32_t>& homes) const {
    // Two entries of a cell pair when one of them is awake, their boxes overlap and this cell
    // holds the low corner of the boxes' intersection (the one cell of the several they may share
    // that reports them). A cell of sleeping entries only is passed over. The particles whose home
    // this cell is are appended to `homes` (the next call's order). Returns the number of cells.
    const std::size_t first_pair = pairs.size();
    // A box has one home among its entries: each entry's id is written, and the write position
    // moves on only for a home (no branch: which entries are homes is as good as random).
    const std::size_t home_base = homes.size();
    homes.resize(home_base + (end - begin));
    std::uint32_t* home = homes.data() + home_base;
    std::size_t cells = 0;
    for (std::size_t run = begin; run < end; ++cells) {
        const std::uint32_t cell = entries_[run].cell;
        std::size_t run_end = run;
        std::uint32_t awake = 0;
        for (; run_end < end && entries_[run_end].cell == cell; ++run_end) {
            const std::uint32_t slot = entries_[run_end].slot;
            awake |= slot & awake_bit;
            *home = slot_id_[slot & slot_mask];
            home += (slot & home_bits) == home_bits;
        }
        for (std::size_t p = run; awake && p + 1 < run_end; ++p) {
            const std::uint32_t sp = entries_[p].slot;
            const FloatBox& bp = slot_box_[sp & slot_mask];
            for (std::size_t q = p + 1; q < run_end; ++q) {
                const std::uint32_t sq = entries_[q].slot;
                const FloatBox& bq = slot_box_[sq & slot_mask];
                // The cell reports the pair when, along each axis, one of the two boxes starts
                // in it: it is then the low corner of the cells they share, met once per pair.
                // One branch for all of it.
                const std::uint32_t both = sp | sq;
                const int skip = int((both & (awake_bit | home_bits)) != (awake_bit | home_bits)) |  // or both asleep
                                 apart(bp, bq);
                if (skip) continue;  // apart even in the rounded-out boxes
                const std::uint32_t i = slot_id_[sp & slot_mask], j = slot_id_[sq & slot_mask];
                pairs.push_back({std::min(i, j), std::max(i, j)});
            }
        }
        run = run_end;
    }
    homes.resize(static_cast<std::size_t>(home - homes.data()));
    if (exact_) keep_exact(pairs, first_pair);
    return cells;
}

void BroadPhase::keep_exact(std::vector<Pair>& pairs, std::size_t from) const {
    // The exact boxes of the pairs from `from` on, fetched ahead: they are out of memory order
    // (a pile's neighbours have random indices), and tested one by one as the cells were
    // scanned, each pair's two boxes came from main memory in turn.
    const SweptBox* box = boxes_->box.data();
    constexpr std::size_t ahead = 8;
    std::size_t kept = from;
    for (std::size_t k = from; k < pairs.size(); ++k) {
        if (k + ahead < pairs.size()) {
            __builtin_prefetch(&box[pairs[k + ahead].a]);
            __builtin_prefetch(&box[pairs[k + ahead].b]);
        }
        if (overlap(box[pairs[k].a], box[pairs[k].b])) pairs[kept++] = pairs[k];
    }
    pairs.resize(kept);
}

}  // namespace pl::collide
