// The state of the particle under the mouse, in a tooltip.
#pragma once

#include "app/picking.hpp"
#include "ui/lab_session.hpp"

namespace pl::app {

void show_particle_tooltip(const ui::LabSession& session, const ParticleRef& particle);

}  // namespace pl::app
