// How tightly a scene's balls start: the share of their starting space they fill (their volume
// fraction). Above 1 they cannot start apart: each would start inside several others (at 1,
// about eight on average). With collisions on that is a burst the overlap pass has to open, and
// thousands of balls in one spot make millions of contact pairs (1e4 balls of 2 cm in a 2 mm
// region: 5e7 pairs, 24 GB and minutes a step), so a preset may not ask for it.
#pragma once

#include "physics/model/scene.hpp"

#include <vector>

namespace pl {

// The most a preset's balls may fill of their starting space when collisions are on
// (io/preset_reader.cpp).
constexpr double max_start_volume_fraction = 1.0;

// An emitter's balls: their mean volume times the count, over the box they can take (the box of
// possible centres, clamped into the room as the positions are, grown by the mean radius on
// every side). 0 without particles.
double emitted_volume_fraction(const Emitter& emitter, const Room& room);

// Listed balls: their volume over the box their centres span, grown by the mean radius on every
// side. It catches a list whose balls all crowd one spot; a crowd beside a few balls far away
// spans a large box, and passes. 0 without particles.
double listed_volume_fraction(const std::vector<ParticleSpec>& particles);

}  // namespace pl
