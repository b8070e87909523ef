// Broad phase of particle-particle collisions: every pair of particles whose swept boxes (the
// axis-aligned box around the sphere over one step, from its start to its end position) overlap.
//
// A uniform grid, rebuilt each step: each box is entered in every cell it overlaps, the entries
// are sorted by the cells' linear index (x + X y + X Y z), and a pair is tested only among the
// entries of one cell, and reported only by the cell that holds the low corner of the two
// boxes' intersection, so it is met once (Ericson, "Real-Time Collision Detection", 2005,
// sec. 7.1-7.2; Le Grand, "Broad-Phase Collision Detection with CUDA", GPU Gems 3, ch. 32, 2007:
// cell entries, a sort, and the "home cell" rule). Nothing is looked up around a particle: the
// cost is a few passes per particle, with no hash-table misses, at any n.
//
// The sort is a counting sort: one pass when the cells are not many more than the boxes (a gas,
// a pile), else LSD radix passes of 11-bit digits. The boxes are entered in the order of the last
// call's cells (a particle moves a fraction of a cell in a step), so the pass writes the entries
// almost in sequence instead of scattering them over memory; only the boxes are read out of
// order (one 48-byte box per particle, fetched ahead). An entry is 8 bytes, a cell and a slot
// (the box's place in that order); the boxes, rounded out to floats, are written once per call
// in slot order, where the scan reads a cell's boxes from the slots of nearby cells.
//
// The cell is a power of two times the median box, chosen from the last call's mean entries per
// cell: a dilute gas gets cells several boxes wide (about one entry per particle and per cell), a
// dense pile cells of one box (eight entries per particle, about nine per cell). A few big or fast
// balls among many small ones do not make the grid coarse: they span more cells, and those
// spanning more than `max_cells` are tested against every other particle.
//
// Every stage runs on the threads it is given (the boxes in slices of particles, the radix sort
// with a histogram per slice, the scan in slices of cells), and every order is fixed: the same
// pairs, in the same order, on any number of threads.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace pl::collide {

// Two particles, a < b. Lists of pairs are sorted by (a, b).
struct Pair {
    std::uint32_t a = 0, b = 0;
    friend bool operator==(const Pair&, const Pair&) = default;
    friend bool operator<(const Pair& p, const Pair& q) { return p.a != q.a ? p.a < q.a : p.b < q.b; }
};

// A swept box: the axis-aligned box around the sphere over one step, from its start to its end.
struct SweptBox {
    double lo[3], hi[3];
};

inline bool overlap(const SweptBox& a, const SweptBox& b) {
    return a.lo[0] <= b.hi[0] && b.lo[0] <= a.hi[0] && a.lo[1] <= b.hi[1] && b.lo[1] <= a.hi[1] && a.lo[2] <= b.hi[2] &&
           b.lo[2] <= a.hi[2];
}

// Whether `inner` lies inside `outer` (false where either holds a NaN).
inline bool contains(const SweptBox& outer, const SweptBox& inner) {
    return inner.lo[0] >= outer.lo[0] && inner.lo[1] >= outer.lo[1] && inner.lo[2] >= outer.lo[2] &&
           inner.hi[0] <= outer.hi[0] && inner.hi[1] <= outer.hi[1] && inner.hi[2] <= outer.hi[2];
}

// Swept boxes, one per particle index (one box in one cache line or two: the broad phase reads
// them in the order of space, not of the indices); `ids` lists the particles that take part
// (frozen ones are left out), in increasing order.
struct SweptBoxes {
    std::vector<SweptBox> box;
    std::vector<std::uint32_t> ids;
    // Per particle index, the farthest its sphere moved along an axis over the step (sized with
    // the boxes by resize), and the largest of them (0: nothing moved): they size the pair
    // cache's fat boxes (pair_cache.hpp).
    std::vector<float> move;
    double reach = 0.0;

    void resize(std::size_t n) {
        box.resize(n);
        move.resize(n);
    }
    bool overlap(std::uint32_t i, std::uint32_t j) const { return collide::overlap(box[i], box[j]); }
    double extent(std::uint32_t i) const;  // the box's largest side
};

// The region the boxes of `ids` take (low and high corners) and their median extent, from an
// evenly strided sample of at most 1024 boxes (the same on every run); the region on up to
// `threads` threads. At least one id. `scratch` keeps its buffers from call to call.
struct BoxSpread {
    double low[3], high[3];
    double median;
};
struct BoxSpreadScratch {
    std::vector<double> sample;
    std::vector<BoxSpread> parts;  // per task
};
BoxSpread spread_of(const SweptBoxes& boxes, std::size_t threads, BoxSpreadScratch& scratch);

class BroadPhase {
public:
    static constexpr std::size_t max_cells = 512;  // cells a box may span before it is "big"

    // Replaces `pairs` by every overlapping pair of `boxes.ids`, sorted. Keeps its buffers from
    // call to call: after the first steps it allocates nothing. With `asleep` (1 per particle
    // index for a sleeping one), pairs of two sleeping particles are left out. `threads` > 1
    // scans the cells in that many threads' share of slices (the pairs are sorted at the end, so
    // the result is the same on any number of threads; the cell size depends only on the calls
    // before, never on the threads).
    // With `exact` false, the pairs are those whose boxes rounded out to floats overlap: a few
    // more, for a caller that tests the exact boxes itself (the pair cache), and no box is read
    // out of memory order in the scan.
    void find_pairs(const SweptBoxes& boxes, std::vector<Pair>& pairs, const std::uint8_t* asleep = nullptr,
                    std::size_t threads = 1, bool exact = true);

    // After a call: appends to `out` the particles of the last call whose box (rounded out to
    // floats) meets `box` in a cell both take, or that were big (each may come more than once),
    // and returns true; or returns false, appending nothing, when `box` would span more than
    // max_cells cells of the last call's grid. The pair cache mends its pairs with it when a few
    // boxes have moved (pair_cache.hpp).
    bool near(const SweptBox& box, std::vector<std::uint32_t>& out) const;

    // The particles of the last call in the order of their home cells (then the big ones): an
    // order of space, which the contact solver lays its bodies out in.
    const std::vector<std::uint32_t>& order() const { return order_; }
    double cell_size() const { return cell_; }             // of the last call
    std::size_t big_count() const { return big_.size(); }    // particles tested against all, last call
    std::size_t entry_count() const { return entry_count_; }  // cell entries, last call

private:
    // A box entered in a cell: the cell, and the box's slot (its place in the order the boxes
    // were entered in) with flags. 8 bytes: the sort moves little (at 3.4 entries a box, entries
    // that carried their box made the sort and the scan move 110 bytes a particle).
    // In Entry::slot: the particle is awake; the box starts in this cell along x, y, z (all three:
    // the cell of its low corner, its home).
    static constexpr std::uint32_t awake_bit = 0x80000000u;
    static constexpr std::uint32_t first_x_bit = 0x10000000u, first_y_bit = 0x20000000u, first_z_bit = 0x40000000u;
    static constexpr std::uint32_t home_bits = first_x_bit | first_y_bit | first_z_bit;
    static constexpr std::uint32_t slot_mask = first_x_bit - 1;
    struct Entry {
        std::uint32_t cell;  // linear cell index
        std::uint32_t slot;  // the box's slot, with awake_bit and the first_*_bits
    };
    // A box's slot with the bits of the axes along which the box starts in the entry's cell.
    static std::uint32_t with_firsts(std::uint32_t slot, bool first_x, bool first_y, bool first_z) {
        return slot | (first_x ? first_x_bit : 0u) | (first_y ? first_y_bit : 0u) | (first_z ? first_z_bit : 0u);
    }
    // A box rounded out to floats, in its slot: the scan reads a cell's boxes from the slots of
    // nearby home cells (the slots follow the last call's order of space), which the caches hold.
    struct FloatBox {
        float lo[3], hi[3];
    };
    // 1 when the boxes are apart along some axis, else 0: one expression, no branch (a fat box
    // passes a test about as often as not: a branch per axis would be mispredicted half the time).
    static int apart(const FloatBox& a, const FloatBox& b) {
        return int(a.lo[0] > b.hi[0]) | int(b.lo[0] > a.hi[0]) | int(a.lo[1] > b.hi[1]) | int(b.lo[1] > a.hi[1]) |
               int(a.lo[2] > b.hi[2]) | int(b.lo[2] > a.hi[2]);
    }
    // One thread's share of the particles: the entries it made and the big ones it found.
    struct alignas(64) Part {  // a cache line of its own: the tasks fill theirs at once
        std::vector<Entry> entries;  // the first `fill` of them made by the last call
        std::size_t fill = 0;
        std::vector<std::uint32_t> big;
        std::vector<std::uint32_t> count;  // radix sort histogram of its source
    };
    struct Source {
        const Entry* begin;
        const Entry* end;
    };
    void choose_cell(const SweptBoxes& boxes, std::size_t threads);
    void size_grid(const double (&high)[3], std::size_t boxes);
    std::uint64_t coordinate(double x, int axis) const;
    std::uint64_t linear(std::uint64_t x, std::uint64_t y, std::uint64_t z) const { return x + stride_y_ * y + stride_z_ * z; }
    void reuse_or_reset_order(const SweptBoxes& boxes);
    void enter_boxes(const SweptBoxes& boxes, const std::uint8_t* asleep, std::size_t begin, std::size_t end, Part& part);
    void radix_sort(std::size_t tasks);
    void radix_pass(const std::vector<Source>& sources, Entry* out, int shift, std::uint32_t mask, bool counted);
    void place_digits(std::size_t tasks, std::size_t digits, bool whole_cell);
    std::size_t scan_cells(std::size_t begin, std::size_t end, std::vector<Pair>& pairs,
                           std::vector<std::uint32_t>& homes) const;
    void keep_exact(std::vector<Pair>& pairs, std::size_t from) const;
    std::size_t scan(std::vector<Pair>& pairs, std::size_t threads);
    void merge_slices(std::vector<Pair>& pairs);
    bool by_count(std::size_t pairs) const;
    void count_sort(std::span<const std::vector<Pair>> sources, std::vector<Pair>& pairs);
    void pair_big_ones(const SweptBoxes& boxes, const std::uint8_t* asleep, std::vector<Pair>& pairs) const;
    void adapt_cell(std::size_t cells);
    template <class Task>
    void run(std::size_t tasks, Task&& task);

    int scale_ = 1;  // the cell is 2^scale_ times the median box
    std::size_t threads_ = 1;
    double cell_ = 0.0, inverse_cell_ = 0.0;
    double origin_[3] = {0.0, 0.0, 0.0};  // the low corner of all boxes
    std::uint64_t stride_y_ = 1, stride_z_ = 1, cell_count_ = 1;
    int passes_ = 1, digit_ = 1;  // of the radix sort: digits of digit_ bits
    std::size_t entry_count_ = 0;
    std::vector<std::uint32_t> big_;
    BoxSpreadScratch spread_scratch_;
    const SweptBoxes* boxes_ = nullptr;     // during a call
    bool exact_ = true;                     // during a call
    // The ids in the order of their home cells at the last call, then the big ones: the next call
    // enters the boxes in this order (for the ids it was made from, `ordered_ids_`), and the order
    // they were entered in (slot -> id) with their boxes in floats.
    std::vector<std::uint32_t> order_, ordered_ids_, slot_id_;
    std::vector<FloatBox> slot_box_;
    std::vector<Part> parts_;               // per task of the build
    std::vector<Source> sources_;           // of the radix sort's pass
    std::vector<Entry> entries_, spare_;    // sorted by cell
    std::vector<std::uint32_t> cell_start_;  // each cell's first entry, when the sort took one pass
    std::vector<std::uint32_t> chunk_start_;  // place_digits: each chunk of digits' first entry
    std::vector<std::size_t> slice_start_;  // slice boundaries (at cell boundaries), when threaded
    std::vector<std::size_t> slice_cells_;
    std::vector<std::vector<Pair>> slice_pairs_;  // per slice, when threaded
    std::vector<std::vector<std::uint32_t>> slice_homes_;
    std::vector<std::size_t> run_end_;            // the merge's sorted runs
    std::vector<Pair> merged_;
    std::vector<std::uint32_t> first_pair_of_;  // the counting sort's: a bin per particle index
};

// The reference: every pair tested, O(n^2).
void all_pairs(const SweptBoxes& boxes, std::vector<Pair>& pairs);

}  // namespace pl::collide
