// Counting the pairs of spheres that overlap, in time linear in their number, stopping as soon as
// the count passes a limit: a preset's listed balls are judged by it before any step is taken
// (physics/model/start_packing.hpp). A clump of 1e4 balls at one point is 5e7 pairs, which the
// count leaves after `limit + 1` of them, whatever lies around the clump.
//
// A hierarchical uniform grid (Ericson, "Real-Time Collision Detection", 2005, sec. 7.2.2;
// Mirtich's hierarchical hash, 1996): level L has cells of 2^L times the base cell, and a sphere
// sits in the cell of its centre on the first level whose cell is at least its diameter. Two
// overlapping spheres are then in neighbouring cells (27 of them) of the coarser one's level, so
// each sphere looks through those on its own level and on every coarser one, and each pair is met
// once (on the same level from the lower index). Mixed radii cost a level each, not a coarse
// grid: a few large balls among many small ones do not put the small ones in shared cells.
// Cells are found through a hash table: the room may be vast and nearly empty.
//
// Spheres of one level cannot crowd a cell without overlapping each other, so the tests are
// bounded by a constant per sphere plus the overlaps counted. The one exception is spheres far
// below the base cell, which is at least 2^-40 of the centres' span (so that cell numbers stay
// exact): if the tests pass their own budget the count ends undecided.
#pragma once

#include "physics/model/scene.hpp"

#include <cstddef>
#include <cstdint>
#include <span>

namespace pl {

struct Sphere {
    Vec3 centre{0.0};
    double radius = 0.0;
};

struct OverlapCount {
    std::size_t pairs = 0;     // overlapping pairs counted: all of them, or limit + 1
    bool over_limit = false;   // the count stopped at limit + 1
    bool undecided = false;    // the tests' budget ran out first (spheres far below the base cell)
    // The deepest overlap counted, as a share of the pair's contact distance (0: none): its
    // spheres (a < b) and its depth in metres.
    std::uint32_t deepest_a = 0, deepest_b = 0;
    double deepest_depth = 0.0, deepest_share = 0.0;
};

// Pairs whose centres are closer than (r_a + r_b)(1 - tolerance): with a tolerance, balls placed
// touching (Newton's cradle, a rack of pool balls) are not counted for the round-off of their
// positions. Every radius must be positive and every centre finite.
OverlapCount count_overlaps(std::span<const Sphere> spheres, std::size_t limit, double tolerance);

}  // namespace pl
