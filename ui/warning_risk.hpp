// Which warnings put a number at risk. The engine warns once per particle and kind whenever a
// particle leaves its drag model's validity range, but out of range is not always wrong: a
// tennis ball under constant-Cd drag passes Re < 1e3 near every apex and before it rests, where
// drag is a thousandth of gravity and the model's error cannot move any result. The Warnings tab
// keeps those as notes; the count in the status bar and on the tab is of warnings at risk.
#pragma once

#include "physics/stepping/simulation.hpp"
#include "physics/stepping/warnings.hpp"

namespace pl::ui {

// Drag-model error (relative to the smooth-sphere correlation Cd(Re), valid for 0 < Re < 1e6)
// below this fraction of the particle's acceleration scale, max(|g|, reference drag), puts no
// number at risk.
inline constexpr double negligible_drag_error = 0.01;

// The drag acceleration error the warning's model makes at the Re it reported, as a fraction of
// the acceleration scale; +inf where there is no reference (Re beyond the correlation's range).
double drag_error_fraction(const Warning& w, const Simulation& sim);

// Out-of-range drag with a negligible error is a note; every other warning (Mach, stability,
// a frozen particle, drag whose error matters) puts a number at risk.
bool puts_number_at_risk(const Warning& w, const Simulation& sim);

}  // namespace pl::ui
