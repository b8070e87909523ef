#include "physics/model/wind.hpp"

#include "physics/model/random.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace pl {

WindField::WindField(const WindSettings& settings, const Room& room) : s_(settings), floor_y_(room.floor_y()) {
    const double len = glm::length(s_.vortex_axis);
    axis_ = len > 0 ? s_.vortex_axis / len : Vec3(0, 1, 0);
    SplitMix64 rng(s_.gust_seed);
    const double base = 2.0 * std::numbers::pi / std::max(s_.gust_period_s, 1e-9);
    for (int a = 0; a < 3; ++a) {
        double sum = 0;
        for (int k = 0; k < 3; ++k) {
            omega_[a][k] = base * (0.5 + 1.5 * rng.uniform01()) * (k + 1);
            phase_[a][k] = 2.0 * std::numbers::pi * rng.uniform01();
            weight_[a][k] = 1.0 / (k + 1);
            sum += weight_[a][k];
        }
        for (int k = 0; k < 3; ++k) weight_[a][k] /= sum;
    }
}

Vec3 WindField::at(const Vec3& x, double t) const {
    switch (s_.kind) {
        case WindKind::none: return Vec3(0.0);
        case WindKind::constant: return s_.velocity;
        case WindKind::gust: {
            Vec3 w = s_.velocity;
            for (int a = 0; a < 3; ++a) {
                double s = 0;
                for (int k = 0; k < 3; ++k) s += weight_[a][k] * std::sin(omega_[a][k] * t + phase_[a][k]);
                w[a] += s_.gust_amplitude[a] * s;
            }
            return w;
        }
        case WindKind::shear: {
            // Power-law atmospheric boundary layer (Hellmann): u(z) = u_ref (z / z_ref)^alpha.
            const double z = std::max(0.0, x.y - floor_y_);
            return s_.velocity * std::pow(z / s_.reference_height_m, s_.shear_exponent);
        }
        case WindKind::vortex: {
            // Rankine vortex: solid-body core, irrotational 1/r outside.
            const Vec3 d = x - s_.vortex_center;
            const Vec3 radial = d - glm::dot(d, axis_) * axis_;
            const double r = glm::length(radial);
            if (r <= 0.0) return Vec3(0.0);
            const double rc = s_.vortex_core_radius_m;
            const double speed = r < rc ? s_.vortex_max_speed * r / rc : s_.vortex_max_speed * rc / r;
            return speed * glm::cross(axis_, radial / r);
        }
    }
    return Vec3(0.0);
}

}  // namespace pl
