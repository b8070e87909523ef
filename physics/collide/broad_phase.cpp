#include "physics/collide/broad_phase.hpp"

#include "physics/collide/slices.hpp"
#include "physics/stepping/thread_pool.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace pl::collide {
namespace {

constexpr double most_cells_per_axis = 2097151.0;  // 2^21 - 1 (and the linear index fits 32 bits)
constexpr int radix_bits = 11;                      // a 2048-bin histogram stays in the L1 cache
constexpr int largest_scale = 4;                    // the cell is at most 16 median boxes

// x in float, rounded down (below) or up (above), without a branch: moved by more than the
// conversion's half-ulp error (|x| 2^-24) before rounding to nearest; 1e-30 covers x = 0.
float below(double x) { return static_cast<float>(x - (std::abs(x) * 0x1p-22 + 1e-30)); }
float above(double x) { return static_cast<float>(x + (std::abs(x) * 0x1p-22 + 1e-30)); }

}  // namespace

double SweptBoxes::extent(std::uint32_t i) const {
    const SweptBox& b = box[i];
    return std::max({b.hi[0] - b.lo[0], b.hi[1] - b.lo[1], b.hi[2] - b.lo[2]});
}

template <class Task>
void BroadPhase::run(std::size_t tasks, Task&& task) {
    if (tasks == 1) return task(std::size_t{0});
    ThreadPool::shared().run(tasks, threads_, task);
}

std::uint64_t BroadPhase::coordinate(double x, int axis) const {
    // x >= the origin: truncation is the floor (through a signed conversion: one instruction; the
    // value is below 2^21). One expression for every box and corner, so a corner shared by two
    // boxes lands in the same cell for both.
    return static_cast<std::uint64_t>(static_cast<std::int64_t>((x - origin_[axis]) * inverse_cell_));
}

BoxSpread spread_of(const SweptBoxes& boxes, std::size_t threads, BoxSpreadScratch& scratch) {
    const std::size_t m = boxes.ids.size(), stride = std::max<std::size_t>(1, m / 1024);
    std::vector<double>& sample = scratch.sample;
    sample.clear();
    for (std::size_t k = 0; k < m; k += stride) sample.push_back(boxes.extent(boxes.ids[k]));
    const auto middle = sample.begin() + static_cast<std::ptrdiff_t>(sample.size() / 2);
    std::nth_element(sample.begin(), middle, sample.end());
    std::vector<BoxSpread>& parts = scratch.parts;
    parts.resize(range_tasks(m, threads));
    for_ranges(m, threads, [&](std::size_t begin, std::size_t end, std::size_t task) {
        const SweptBox* box = boxes.box.data();
        double low[3], high[3];  // locals: kept in registers
        for (int k = 0; k < 3; ++k) {
            low[k] = box[boxes.ids[begin]].lo[k];
            high[k] = box[boxes.ids[begin]].hi[k];
        }
        for (std::size_t n = begin; n < end; ++n)
            for (int k = 0; k < 3; ++k) {
                low[k] = std::min(low[k], box[boxes.ids[n]].lo[k]);
                high[k] = std::max(high[k], box[boxes.ids[n]].hi[k]);
            }
        for (int k = 0; k < 3; ++k) {
            parts[task].low[k] = low[k];
            parts[task].high[k] = high[k];
        }
    });
    BoxSpread spread = parts[0];
    for (const BoxSpread& part : parts)
        for (int k = 0; k < 3; ++k) {
            spread.low[k] = std::min(spread.low[k], part.low[k]);
            spread.high[k] = std::max(spread.high[k], part.high[k]);
        }
    spread.median = *middle;
    return spread;
}

void BroadPhase::choose_cell(const SweptBoxes& boxes, std::size_t threads) {
    // The region of the boxes rounded out to floats (monotonic), and a cell 2^scale_ times the
    // median box (> 0: every box holds a sphere).
    const BoxSpread spread = spread_of(boxes, threads, spread_scratch_);
    double high[3];
    for (int k = 0; k < 3; ++k) {
        origin_[k] = below(spread.low[k]);
        high[k] = above(spread.high[k]);
    }
    cell_ = std::ldexp(spread.median, scale_);
    size_grid(high, boxes.ids.size());
}

void BroadPhase::size_grid(const double (&high)[3], std::size_t boxes) {
    // The linear index of every cell must fit 32 bits (and each coordinate 21): in a vast, nearly
    // empty room the cells grow until it does, which costs nothing there. (Bounded: 2048
    // doublings take any finite double past any finite span.)
    for (int doubling = 0; doubling < 2048; ++doubling) {
        inverse_cell_ = 1.0 / cell_;
        std::uint64_t cells[3];
        bool fits = true;
        for (int k = 0; k < 3; ++k) {
            const double span = (high[k] - origin_[k]) * inverse_cell_;
            fits = fits && span < most_cells_per_axis;
            cells[k] = fits ? coordinate(high[k], k) + 1 : 0;
        }
        if (fits && cells[0] * cells[1] * cells[2] <= 0xffffffffull) {
            stride_y_ = cells[0];
            stride_z_ = cells[0] * cells[1];
            cell_count_ = stride_z_ * cells[2];
            const int bits = std::max(1, static_cast<int>(std::bit_width(cell_count_ - 1)));
            // One counting-sort pass when the cells are not many more than the boxes (its
            // histogram then costs no more than the entries): the boxes come in the order of
            // their last cells, so its writes run almost in sequence. Else LSD radix passes.
            const int one_pass = std::max(radix_bits, static_cast<int>(std::bit_width(2 * boxes)));
            passes_ = bits <= one_pass ? 1 : (bits + radix_bits - 1) / radix_bits;
            digit_ = (bits + passes_ - 1) / passes_;
            return;
        }
        cell_ *= 2.0;
    }
    stride_y_ = stride_z_ = cell_count_ = 1;  // not finite: every box in one cell
    passes_ = digit_ = 1;
}

void BroadPhase::reuse_or_reset_order(const SweptBoxes& boxes) {
    // The last call's order of space serves while the same particles take part (they moved a
    // step at most: the order is still nearly that of their cells); else the order of the ids.
    if (ordered_ids_ != boxes.ids || order_.size() != boxes.ids.size()) {
        ordered_ids_ = boxes.ids;
        order_ = boxes.ids;
    }
}

void BroadPhase::enter_boxes(const SweptBoxes& boxes, const std::uint8_t* asleep, std::size_t begin, std::size_t end,
                             Part& part) {
    part.fill = 0;
    part.big.clear();
    const std::uint32_t digit_mask = (1u << digit_) - 1;  // the radix sort's first digit, counted here
    part.count.assign(std::size_t{digit_mask} + 1, 0);
    std::uint32_t* count = part.count.data();
    const std::uint32_t* order = slot_id_.data();
    const SweptBox* box = boxes.box.data();
    constexpr std::size_t ahead = 16;  // the order of space is not that of memory: fetch ahead
    for (std::size_t n = begin; n < end; ++n) {
        if (n + ahead < end) __builtin_prefetch(&box[order[n + ahead]]);
        const std::uint32_t i = order[n];
        const SweptBox& b = box[i];
        // The box rounded out to floats decides everything here: its cells, and (in the scan)
        // which cell reports a pair, from values that are the same in every cell.
        float lo_f[3], hi_f[3];
        std::uint64_t lo[3], hi[3];
        for (int k = 0; k < 3; ++k) {
            lo_f[k] = below(b.lo[k]);
            hi_f[k] = above(b.hi[k]);
            lo[k] = coordinate(lo_f[k], k);
            hi[k] = coordinate(hi_f[k], k);
        }
        const std::uint64_t spanned = (hi[0] - lo[0] + 1) * (hi[1] - lo[1] + 1) * (hi[2] - lo[2] + 1);
        if (spanned > max_cells) {
            part.big.push_back(i);
            continue;
        }
        FloatBox& slot_box = slot_box_[n];
        for (int k = 0; k < 3; ++k) {
            slot_box.lo[k] = lo_f[k];
            slot_box.hi[k] = hi_f[k];
        }
        if (part.entries.size() < part.fill + max_cells)  // grown, never shrunk: no zeroing a call
            part.entries.resize(std::max(2 * part.entries.size(), part.fill + max_cells));
        Entry* out = part.entries.data() + part.fill;
        const std::uint32_t slot = static_cast<std::uint32_t>(n) | (asleep && asleep[i] ? 0u : awake_bit);
        if (spanned > 1 && hi[0] - lo[0] <= 1 && hi[1] - lo[1] <= 1 && hi[2] - lo[2] <= 1) {
            // Two cells along some axis, at most two along each (a box a fair share of the cell
            // wide, which crosses a boundary about as often as not): the eight of a 2 x 2 x 2
            // block written, and kept where they lie in the box, without a branch.
            std::size_t kept = 0;
            for (std::uint64_t dz = 0; dz <= 1; ++dz)
                for (std::uint64_t dy = 0; dy <= 1; ++dy)
                    for (std::uint64_t dx = 0; dx <= 1; ++dx) {
                        const auto cell = static_cast<std::uint32_t>(linear(lo[0] + dx, lo[1] + dy, lo[2] + dz));
                        out[kept] = {cell, with_firsts(slot, dx == 0, dy == 0, dz == 0)};
                        const std::uint32_t in =
                            std::uint32_t(lo[0] + dx <= hi[0]) & std::uint32_t(lo[1] + dy <= hi[1]) & std::uint32_t(lo[2] + dz <= hi[2]);
                        count[cell & digit_mask] += in;
                        kept += in;
                    }
            part.fill += kept;
            continue;
        }
        for (std::uint64_t z = lo[2]; z <= hi[2]; ++z)
            for (std::uint64_t y = lo[1]; y <= hi[1]; ++y)
                for (std::uint64_t x = lo[0]; x <= hi[0]; ++x) {
                    Entry& e = *out++;
                    e.cell = static_cast<std::uint32_t>(linear(x, y, z));
                    ++count[e.cell & digit_mask];
                    e.slot = with_firsts(slot, x == lo[0], y == lo[1], z == lo[2]);
                }
        part.fill += static_cast<std::size_t>(spanned);
    }
}

void BroadPhase::radix_pass(const std::vector<Source>& sources, Entry* out, int shift, std::uint32_t mask,
                            bool counted) {
    // One stable counting-sort pass on the digit (cell >> shift) & mask, a histogram per source;
    // the sources are in order, so the destinations of digit d are source 0's, then source 1's...
    const std::size_t tasks = sources.size();
    if (!counted) {
        run(tasks, [&](std::size_t t) {
            std::vector<std::uint32_t>& count = parts_[t].count;
            count.assign(std::size_t{mask} + 1, 0);
            for (const Entry* e = sources[t].begin; e != sources[t].end; ++e) ++count[(e->cell >> shift) & mask];
        });
    }
    // In a single pass the digit is the whole cell: the starts of the cells are kept, for near().
    place_digits(tasks, std::size_t{mask} + 1, shift == 0 && passes_ == 1);
    run(tasks, [&](std::size_t t) {
        std::uint32_t* place = parts_[t].count.data();
        for (const Entry* e = sources[t].begin; e != sources[t].end; ++e) out[place[(e->cell >> shift) & mask]++] = *e;
    });
}

void BroadPhase::place_digits(std::size_t tasks, std::size_t digits, bool whole_cell) {
    // Each source's count of each digit becomes the place of its first entry: digit 0's entries
    // first (source 0's, then source 1's...), then digit 1's. The sums run in chunks of digits on
    // the threads when the digits are many (a one-pass sort's digit is the whole cell: 2^15 of
    // them in a gas of 1e4, 2^18 at 1e5, a serial loop that took a tenth of the main thread's own
    // work in a grid run): each chunk's total, their running sum, then each chunk's places from
    // its start.
    const std::size_t chunks = tasks > 1 && digits >= 8192 ? 4 * tasks : 1;
    chunk_start_.assign(chunks + 1, 0);
    auto digits_of = [&](std::size_t k) { return std::pair{digits * k / chunks, digits * (k + 1) / chunks}; };
    run(chunks, [&](std::size_t k) {
        std::uint32_t total = 0;
        for (auto [d, end] = digits_of(k); d < end; ++d)
            for (std::size_t t = 0; t < tasks; ++t) total += parts_[t].count[d];
        chunk_start_[k + 1] = total;
    });
    for (std::size_t k = 0; k < chunks; ++k) chunk_start_[k + 1] += chunk_start_[k];
    if (whole_cell) cell_start_.resize(digits + 1);
    run(chunks, [&](std::size_t k) {
        std::uint32_t next = chunk_start_[k];
        for (auto [d, end] = digits_of(k); d < end; ++d) {
            if (whole_cell) cell_start_[d] = next;
            for (std::size_t t = 0; t < tasks; ++t) next += std::exchange(parts_[t].count[d], next);
        }
    });
    if (whole_cell) cell_start_[digits] = chunk_start_[chunks];
}

void BroadPhase::radix_sort(std::size_t tasks) {
    // LSD radix sort of the entries by cell, in equal digits of at most 11 bits: stable, so that a
    // cell's entries keep the order of their ids. The first pass reads the parts where they were
    // made; the later ones equal slices of the last pass's output.
    std::size_t total = 0;
    sources_.resize(tasks);
    for (std::size_t t = 0; t < tasks; ++t) {
        sources_[t] = {parts_[t].entries.data(), parts_[t].entries.data() + parts_[t].fill};
        total += parts_[t].fill;
    }
    if (entries_.size() < total) {  // grown, never cleared: no step pays for zeroing them
        entries_.resize(total);
        spare_.resize(total);
    }
    entry_count_ = total;
    const std::uint32_t mask = (1u << digit_) - 1;
    for (int pass = 0; pass < passes_; ++pass) {
        // Every pass writes the other buffer; the last one writes entries_. The first pass's
        // histograms were counted as the entries were made.
        Entry* out = (passes_ - pass) % 2 == 1 ? entries_.data() : spare_.data();
        radix_pass(sources_, out, pass * digit_, mask, pass == 0);
        for (std::size_t t = 0; t < tasks; ++t) sources_[t] = {out + total * t / tasks, out + total * (t + 1) / tasks};
    }
}

void BroadPhase::pair_big_ones(const SweptBoxes& boxes, const std::uint8_t* asleep, std::vector<Pair>& pairs) const {
    // Big particles against all: a pair of two big ones is taken from the side of the lower
    // awake id (or the awake one).
    auto sleeps = [asleep](std::uint32_t i) { return asleep && asleep[i]; };
    for (const std::uint32_t big : big_)
        for (const std::uint32_t j : boxes.ids) {
            if (j == big || (sleeps(big) && sleeps(j)) || !boxes.overlap(big, j)) continue;
            const bool other_big = std::binary_search(big_.begin(), big_.end(), j);
            if (other_big && (sleeps(big) || (!sleeps(j) && j < big))) continue;
            pairs.push_back({std::min(big, j), std::max(big, j)});
        }
}

void BroadPhase::adapt_cell(std::size_t cells) {
    // Aim at a few entries per cell: fewer, and the entries (a sort's work) outnumber the
    // particles for nothing; many more, and the pairs tested in a cell grow as their square.
    // Doubling the cell multiplies a uniform crowd's entries per cell by up to 8, hence the wide
    // band (no flip-flop between two sizes).
    if (cells == 0) return;
    const double per_cell = static_cast<double>(entry_count_) / static_cast<double>(cells);
    if (per_cell < 1.5 && scale_ < largest_scale) ++scale_;
    else if (per_cell > 16.0 && scale_ > 0) --scale_;
}

std::size_t BroadPhase::scan(std::vector<Pair>& pairs, std::size_t threads) {
    // Below a few thousand entries a thread costs more to wake than its share saves.
    const std::size_t slices = threads > 1 && entry_count_ >= 4096 ? 4 * threads : 1;
    order_.clear();
    if (slices == 1) {
        const std::size_t cells = scan_cells(0, entry_count_, pairs, order_);
        if (by_count(pairs.size())) {
            merged_.swap(pairs);
            count_sort({&merged_, 1}, pairs);
        } else {
            std::sort(pairs.begin(), pairs.end());
        }
        return cells;
    }
    // Slices of about equal size, each starting at a cell's first entry.
    slice_start_.assign(slices + 1, entry_count_);
    for (std::size_t k = 0; k < slices; ++k) {
        std::size_t at = entry_count_ * k / slices;
        while (at > 0 && at < entry_count_ && entries_[at].cell == entries_[at - 1].cell) ++at;
        slice_start_[k] = at;
    }
    slice_pairs_.resize(slices);
    slice_homes_.resize(slices);
    slice_cells_.assign(slices, 0);
    run(slices, [&](std::size_t k) {
        const std::size_t begin = slice_start_[k], end = std::max(begin, slice_start_[k + 1]);
        slice_cells_[k] = fill_privately(slice_pairs_[k], [&](std::vector<Pair>& found) {
            return fill_privately(slice_homes_[k], [&](std::vector<std::uint32_t>& homes) {
                return scan_cells(begin, end, found, homes);
            });
        });
    });
    std::size_t cells = 0, found = 0;
    for (std::size_t k = 0; k < slices; ++k) {
        cells += slice_cells_[k];
        found += slice_pairs_[k].size();
        order_.insert(order_.end(), slice_homes_[k].begin(), slice_homes_[k].end());
    }
    if (by_count(found)) {
        count_sort(slice_pairs_, pairs);
    } else {
        run(slices, [&](std::size_t k) { std::sort(slice_pairs_[k].begin(), slice_pairs_[k].end()); });
        merge_slices(pairs);
    }
    return cells;
}

void BroadPhase::find_pairs(const SweptBoxes& boxes, std::vector<Pair>& pairs, const std::uint8_t* asleep,
                            std::size_t threads, bool exact) {
    exact_ = exact;
    pairs.clear();
    big_.clear();
    entry_count_ = 0;
    const std::size_t m = boxes.ids.size();
    if (m < 2) return;
    if (boxes.ids.size() > slot_mask) throw std::length_error("broad phase: 2^28 or more particles");
    threads_ = threads;
    boxes_ = &boxes;
    reuse_or_reset_order(boxes);
    slot_id_.swap(order_);  // entered in the last call's order; the scan makes the next one
    slot_box_.resize(m);
    const std::size_t tasks = range_tasks(m, threads);
    if (parts_.size() < tasks) parts_.resize(tasks);
    choose_cell(boxes, threads);
    run(tasks, [&](std::size_t t) { enter_boxes(boxes, asleep, m * t / tasks, m * (t + 1) / tasks, parts_[t]); });
    for (std::size_t t = 0; t < tasks; ++t) big_.insert(big_.end(), parts_[t].big.begin(), parts_[t].big.end());
    radix_sort(tasks);
    const std::size_t cells = scan(pairs, threads);  // sorted; the home cells' order made
    order_.insert(order_.end(), big_.begin(), big_.end());
    const auto from_grid = static_cast<std::ptrdiff_t>(pairs.size());
    pair_big_ones(boxes, asleep, pairs);
    std::sort(pairs.begin() + from_grid, pairs.end());
    std::inplace_merge(pairs.begin(), pairs.begin() + from_grid, pairs.end());
    adapt_cell(cells);
}

bool BroadPhase::near(const SweptBox& box, std::vector<std::uint32_t>& out) const {
    // The cells of the box clamped to the grid (every entered box lies inside it), each row's
    // entries found from the cells' starts (a one-pass sort), else by a binary search in the
    // sorted entries: a few rows, each a short run.
    const std::uint64_t dims[3] = {stride_y_, stride_z_ / stride_y_, cell_count_ / stride_z_};
    FloatBox query;
    std::uint64_t lo[3], hi[3];
    for (int k = 0; k < 3; ++k) {
        query.lo[k] = below(box.lo[k]);
        query.hi[k] = above(box.hi[k]);
        const double top = static_cast<double>(dims[k] - 1);
        const double from = std::clamp((query.lo[k] - origin_[k]) * inverse_cell_, 0.0, top);
        const double to = std::clamp((query.hi[k] - origin_[k]) * inverse_cell_, 0.0, top);
        if (!(from <= to)) return false;  // not finite
        lo[k] = static_cast<std::uint64_t>(from);
        hi[k] = static_cast<std::uint64_t>(to);
    }
    if ((hi[0] - lo[0] + 1) * (hi[1] - lo[1] + 1) * (hi[2] - lo[2] + 1) > max_cells) return false;
    const Entry* const begin = entries_.data();
    const Entry* const end = begin + entry_count_;
    for (std::uint64_t z = lo[2]; entry_count_ > 0 && z <= hi[2]; ++z)
        for (std::uint64_t y = lo[1]; y <= hi[1]; ++y) {
            const std::uint64_t first = linear(lo[0], y, z), last = linear(hi[0], y, z);
            const Entry* e = passes_ == 1 ? begin + cell_start_[first]
                                          : std::lower_bound(begin, end, first, [](const Entry& a, std::uint64_t c) { return a.cell < c; });
            for (; e != end && e->cell <= last; ++e)
                if (!apart(query, slot_box_[e->slot & slot_mask])) out.push_back(slot_id_[e->slot & slot_mask]);
        }
    out.insert(out.end(), big_.begin(), big_.end());
    return true;
}

void all_pairs(const SweptBoxes& boxes, std::vector<Pair>& pairs) {
    pairs.clear();
    for (std::size_t p = 0; p < boxes.ids.size(); ++p)
        for (std::size_t q = p + 1; q < boxes.ids.size(); ++q)
            if (boxes.overlap(boxes.ids[p], boxes.ids[q])) pairs.push_back({boxes.ids[p], boxes.ids[q]});
}

}  // namespace pl::collide
