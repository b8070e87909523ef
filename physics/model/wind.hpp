// Wind field w(x, t). Drag acts on the velocity relative to the air, v - w.
#pragma once

#include "physics/model/scene.hpp"

#include <array>

namespace pl {

class WindField {
public:
    WindField() = default;
    WindField(const WindSettings& settings, const Room& room);

    WindKind kind() const { return s_.kind; }
    Vec3 at(const Vec3& x, double t) const;

private:
    WindSettings s_;
    double floor_y_ = 0.0;
    Vec3 axis_{0, 1, 0};
    // Gust: three sinusoids per axis with seeded frequencies and phases, weights summing to 1,
    // so |s(t)| <= 1 and the gust never exceeds its amplitude.
    std::array<std::array<double, 3>, 3> omega_{}, phase_{}, weight_{};
};

}  // namespace pl
