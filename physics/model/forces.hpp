// The force sum, assembled at compile time from the model: a term that is off is not
// compiled in, so it costs nothing and is never evaluated (the counters prove it).
// Everything is per unit mass: accelerations and powers in W/kg.
#pragma once

#include "physics/model/drag.hpp"
#include "physics/model/scene.hpp"
#include "physics/model/wind.hpp"

#include <glm/geometric.hpp>

#include <cmath>
#include <cstdint>

namespace pl {

// Time derivative of the flight state: acceleration plus the two ledger rates.
struct Derivative {
    Vec3 a{0.0};
    double drag_power = 0.0;  // energy dissipated by drag (relative to the air), >= 0
    double wind_power = 0.0;  // work done on the particle by the moving air
};

// Linear-drag view of the forces at one state, for the exponential integrator:
// a = g - k (v - w) with k and w frozen over the step.
struct LinearisedForces {
    double k = 0.0;
    Vec3 wind{0.0};
};

template <DragModel Drag, bool HasWind>
struct Forces {
    Vec3 gravity{0.0};
    const WindField* wind = nullptr;
    DragCoefficients drag{};  // of the particle being stepped
    mutable std::uint64_t gravity_evals = 0, drag_evals = 0, wind_evals = 0;

    double drag_rate(const Vec3& u) const {
        if constexpr (Drag == DragModel::linear) {
            return drag.k;
        } else if constexpr (Drag == DragModel::quadratic) {
            return drag.k * std::sqrt(glm::dot(u, u));
        } else if constexpr (Drag == DragModel::sphere_re) {
            return drag.k * sphere_cd_times_re(drag.re_scale * std::sqrt(glm::dot(u, u)));
        } else {
            return 0.0;
        }
    }

    Vec3 air_velocity(const Vec3& x, double t) const {
        if constexpr (HasWind) {
            ++wind_evals;
            return wind->at(x, t);
        } else {
            return Vec3(0.0);
        }
    }

    Derivative operator()(const Vec3& x, const Vec3& v, double t) const {
        ++gravity_evals;
        Derivative d{gravity};
        if constexpr (Drag != DragModel::none) {
            ++drag_evals;
            const Vec3 w = air_velocity(x, t);
            const Vec3 u = v - w;
            const double c = drag_rate(u);
            const Vec3 a_drag = -c * u;
            d.a += a_drag;
            d.drag_power = c * glm::dot(u, u);
            if constexpr (HasWind) d.wind_power = glm::dot(a_drag, w);
        }
        return d;
    }

    LinearisedForces linearise(const Vec3& x, const Vec3& v, double t) const {
        LinearisedForces l;
        if constexpr (Drag != DragModel::none) {
            ++drag_evals;
            l.wind = air_velocity(x, t);
            l.k = drag_rate(v - l.wind);
        }
        return l;
    }
};

}  // namespace pl
