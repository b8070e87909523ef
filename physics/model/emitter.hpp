// Seeded particle emitter: the same Emitter always yields the same particles.
#pragma once

#include "physics/model/scene.hpp"

namespace pl {

// Positions are clamped so every sphere starts inside the room. `limit` stops after that many
// particles (the first ones are the same whatever the limit: one draw sequence), so a caller that
// needs only particle 0 of a 2e6-particle emitter does not build all of them.
std::vector<ParticleSpec> emit_particles(const Emitter& emitter, const Room& room,
                                         std::size_t limit = static_cast<std::size_t>(-1));
// The same particles appended to `out` (reserved once, so millions are never copied).
void append_emitted(const Emitter& emitter, const Room& room, std::vector<ParticleSpec>& out,
                    std::size_t limit = static_cast<std::size_t>(-1));

// The share of the emitter's starting space its balls fill: their mean volume times the count,
// over the box the balls can take (the box of possible centres, clamped into the room as the
// positions are, grown by the mean radius on every side). Above 1 they cannot start apart: each
// would start inside several others (at 1, about eight on average), which with collisions on is
// a burst the overlap pass has to open, and a clump of thousands in one spot makes millions of
// contacts. 0 without particles.
double emitted_volume_fraction(const Emitter& emitter, const Room& room);
// The most a preset's emitter may pack when collisions are on (io/preset_reader.cpp).
constexpr double max_emitted_volume_fraction = 1.0;

}  // namespace pl
