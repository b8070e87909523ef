// A launch velocity in the Launch section's terms: speed, elevation above the horizontal plane
// and azimuth from +x towards +z (degrees), and back. Shared by the Launch section and the aim
// gesture in the 3D view.
#pragma once

#include "physics/model/scene.hpp"

namespace pl::ui {

// The Launch section's speed range ends here; an aim never asks for more.
constexpr double max_launch_speed_mps = 1e3;

struct LaunchPolar {
    double speed_mps = 0.0, elevation_deg = 0.0, azimuth_deg = 0.0;
};

// Elevation 0 for a zero velocity, azimuth 0 for a vertical one.
LaunchPolar launch_polar(const Vec3& velocity);
Vec3 launch_velocity(const LaunchPolar& polar);

}  // namespace pl::ui
