// Runs a scene apart from the live one and pins it: how a clicked sweep point joins the pinned
// runs (ghost trajectories, faded curves, a row in the Compare table) beside the live run,
// which the click leaves as it was.
#pragma once

#include "ui/lab_session.hpp"

#include <string>

namespace pl::ui {

// Runs `scene` for `duration_s` simulated seconds, recorded as the live run is (the same
// fixed-interval samples and live metrics), and pins its first variant under "run N: `what`".
// Returns the status line; a scene that cannot run here pins nothing and says why.
std::string pin_scene(LabSession& s, const Scene& scene, double duration_s, const std::string& what);

}  // namespace pl::ui
