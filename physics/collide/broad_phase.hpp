// Broad phase of particle-particle collisions: every pair of particles whose swept boxes (the
// axis-aligned box around the sphere over one step, from its start to its end position) overlap.
// A hashed uniform grid in structure-of-arrays form, rebuilt each step by a counting sort of the
// particles by cell, finds them in linear time; the cell is the largest box, at most twice the
// median box. Particles whose box is larger than a cell (a few big or fast balls among many small
// ones) stay out of the grid and are tested against every other particle, so they do not make
// the cells coarse.
// The same design as the uniform grids of Box2D v3's broad phase predecessors and of GPU particle
// codes (Green, "Particle Simulation using CUDA", 2010: hash, sort by cell, scan neighbours).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace pl::collide {

// Two particles, a < b. Lists of pairs are sorted by (a, b).
struct Pair {
    std::uint32_t a = 0, b = 0;
    friend bool operator==(const Pair&, const Pair&) = default;
    friend bool operator<(const Pair& p, const Pair& q) { return p.a != q.a ? p.a < q.a : p.b < q.b; }
};

// Swept boxes, one per particle index (structure of arrays); `ids` lists the particles that take
// part (frozen ones are left out), in increasing order.
struct SweptBoxes {
    std::vector<double> lo[3], hi[3];
    std::vector<std::uint32_t> ids;

    void resize(std::size_t n);
    bool overlap(std::uint32_t i, std::uint32_t j) const {
        return lo[0][i] <= hi[0][j] && lo[0][j] <= hi[0][i] && lo[1][i] <= hi[1][j] && lo[1][j] <= hi[1][i] &&
               lo[2][i] <= hi[2][j] && lo[2][j] <= hi[2][i];
    }
    double extent(std::uint32_t i) const;  // the box's largest side
};

class BroadPhase {
public:
    // Replaces `pairs` by every overlapping pair of `boxes.ids`, sorted. Keeps its buffers from
    // call to call: after the first steps it allocates nothing. With `asleep` (1 per particle
    // index for a sleeping one), pairs of two sleeping particles are left out: only the awake
    // particles scan their neighbours, so a pile asleep costs the grid's build and no more.
    // `threads` > 1 scans the grid in that many threads' share of slices (the pairs are sorted
    // at the end, so the result is the same on any number).
    void find_pairs(const SweptBoxes& boxes, std::vector<Pair>& pairs, const std::uint8_t* asleep = nullptr,
                    std::size_t threads = 1);

    double cell_size() const { return cell_; }           // of the last call
    std::size_t big_count() const { return big_.size(); }  // particles tested against all, last call

private:
    using Cell = std::array<std::int64_t, 3>;
    Cell cell_of(const SweptBoxes& boxes, std::uint32_t i) const;  // of the box's centre
    void build_grid(const SweptBoxes& boxes);
    void scan_slots(std::size_t begin, std::size_t end, const std::uint8_t* asleep, std::vector<Pair>& pairs) const;
    std::size_t bucket_of(std::int64_t ix, std::int64_t iy, std::int64_t iz) const;

    double cell_ = 0.0;
    std::vector<double> extents_;
    std::vector<std::uint32_t> small_, big_;
    std::vector<Cell> cell_of_;                // per particle index: its grid cell (small ones)
    std::vector<std::uint32_t> bucket_;        // per particle index: its grid bucket (small ones)
    std::vector<std::uint32_t> bucket_start_;  // counting sort: first slot of each bucket, then the end
    std::vector<std::uint32_t> next_;          // counting sort: next free slot of each bucket
    std::vector<std::uint32_t> sorted_;        // small particles ordered by bucket
    // Per slot of sorted_: the particle's cell and box, so that a bucket's particles are read from
    // consecutive memory and neighbouring particles are scanned one after the other.
    std::vector<Cell> slot_cell_;
    std::vector<double> slot_lo_[3], slot_hi_[3];
    std::vector<std::vector<Pair>> slice_pairs_;  // per slice of slots, when threaded
};

// The reference: every pair tested, O(n^2).
void all_pairs(const SweptBoxes& boxes, std::vector<Pair>& pairs);

}  // namespace pl::collide
