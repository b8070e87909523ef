// Seeded particle emitter: the same Emitter always yields the same particles.
#pragma once

#include "physics/model/scene.hpp"

namespace pl {

// Positions are clamped so every sphere starts inside the room.
std::vector<ParticleSpec> emit_particles(const Emitter& emitter, const Room& room);

}  // namespace pl
