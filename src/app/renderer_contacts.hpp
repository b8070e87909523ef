// The pile in the 3D view: collision contacts as line segments coloured by their load, and the
// slate tint of sleeping particles. Both read what the collision pass kept of the last step
// (Simulation::collision_pass, Simulation::asleep); neither costs anything without collisions.
#pragma once

#include "app/renderer_lines.hpp"
#include "physics/stepping/experiment.hpp"

#include <optional>

namespace pl::app {

// More contacts than this in a pane are thinned to every k-th (a million-ball pile has millions
// of contacts; its lines would be a solid block anyway).
constexpr std::size_t max_contact_segments = 100'000;

// Contacts of the last step that carried a load (lambda_n > 0) in the variants a pane shows: a
// pair as a line between the two centres, a wall contact from the centre to the contact point.
// Colour and opacity grow with lambda_n over the largest lambda_n in the pane (faint amber to
// white), so the chains that carry a pile's weight stand out. A pair whose centres are now apart
// by more than 1.5 times their contact distance is left out: one of them was launched or kicked
// after the step (the pair is listed again, or not, at the next). Returns the contacts appended.
std::size_t append_contacts(const Experiment& e, std::optional<std::size_t> only_variant, LineSegments& out);

// A sleeping particle's colour: mostly slate blue-grey, 15% of its own colour kept so that
// overlaid variants stay told apart.
glm::vec3 sleeping_tint(glm::vec3 own);

}  // namespace pl::app
