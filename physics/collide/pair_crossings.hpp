// Pairs that crossed each other within one step: a check after the pass, for the steps too long
// for it. The pass meets a pair on straight paths from the step's start to its end (after any
// wall bounce in the kernel), so a ball that crosses the room in a step, or a heavy ball driven
// through a light one held by a wall in one long step, can end on the far side of the other ball
// without a contact ever being seen.
//
// A pair is reported when it started the step apart (closer than the contact distance by at most
// half the overlap warning limit), ended it on the other side of each other (the separation
// turned by more than 90 degrees), and the straight path of the separation between them passes
// inside the contact distance: the balls went through each other, or round each other faster
// than the step can show. With the separation moving less than the contact distance in a step it
// cannot turn that far while the balls stay apart, so a step short enough for the pass never
// reports one.
#pragma once

#include "physics/collide/broad_phase.hpp"
#include "physics/stepping/particle_state.hpp"

#include <cstdint>
#include <vector>

namespace pl::collide {

struct PairCrossing {
    std::uint32_t a, b;
    double travel;  // how far the separation moved in the step, in contact distances
};

// Appends to `out` the pairs of `pairs` that crossed this step, from their start positions
// `start` (per particle) to the positions in `s`; pairs of two sleeping particles are skipped.
// `touching_share`: the deepest start overlap, as a share of the contact distance, still counted apart.
void find_crossings(const std::vector<Pair>& pairs, const std::vector<Vec3>& start, const ParticleState& s,
                    const std::vector<std::uint8_t>& asleep, double touching_share, std::vector<PairCrossing>& out);

}  // namespace pl::collide
