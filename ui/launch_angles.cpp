#include "ui/launch_angles.hpp"

#include <glm/geometric.hpp>

#include <cmath>

namespace pl::ui {

namespace {
constexpr double pi = 3.14159265358979323846;
}

LaunchPolar launch_polar(const Vec3& v) {
    LaunchPolar p;
    p.speed_mps = glm::length(v);
    const double horizontal = std::hypot(v.x, v.z);
    p.elevation_deg = p.speed_mps > 0.0 ? std::atan2(v.y, horizontal) * 180.0 / pi : 0.0;
    p.azimuth_deg = horizontal > 0.0 ? std::atan2(v.z, v.x) * 180.0 / pi : 0.0;
    return p;
}

Vec3 launch_velocity(const LaunchPolar& p) {
    const double el = p.elevation_deg * pi / 180.0, az = p.azimuth_deg * pi / 180.0;
    return p.speed_mps * Vec3(std::cos(el) * std::cos(az), std::sin(el), std::cos(el) * std::sin(az));
}

}  // namespace pl::ui
