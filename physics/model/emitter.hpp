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

}  // namespace pl
