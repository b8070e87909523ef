// How tightly a scene's balls start: the emitter's by the share of their starting space they fill
// (their volume fraction), the listed ones by their overlaps. Above a fraction of 1 balls cannot
// start apart: each would start inside several others (at 1, about eight on average). With
// collisions on that is a burst the overlap pass has to open, and thousands of balls in one spot
// make millions of contact pairs (1e4 balls of 2 cm in a 2 mm region: 5e7 pairs, 24 GB and
// minutes a step), so a preset may not ask for it.
#pragma once

#include "physics/model/scene.hpp"
#include "physics/model/sphere_overlaps.hpp"

#include <vector>

namespace pl {

// The most a preset's balls may fill of their starting space when collisions are on
// (io/preset_reader.cpp).
constexpr double max_start_volume_fraction = 1.0;

// An emitter's balls: their mean volume times the count, over the box they can take (the box of
// possible centres, clamped into the room as the positions are, grown by the mean radius on
// every side). 0 without particles.
double emitted_volume_fraction(const Emitter& emitter, const Room& room);

// Listed balls are judged by their overlaps instead (a box they span says nothing of a crowd
// beside a few balls far away): at most this many overlapping pairs per ball. Balls placed at
// random at the largest volume fraction above overlap 8 others each on average (4 pairs a ball),
// a packing placed a hair too tight 12 (6 pairs a ball); a clump of 1e4 balls at one point 5e3.
constexpr double max_start_overlaps_per_ball = 8.0;

// The listed balls' overlapping pairs, counted up to max_start_overlaps_per_ball per ball (then
// over_limit): overlaps the collision pass leaves alone (below CollisionPass::allowed_overlap of
// the contact distance: balls placed touching) are not counted.
OverlapCount listed_overlaps(const std::vector<ParticleSpec>& particles);

}  // namespace pl
