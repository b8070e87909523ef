// One step of each integration method for a single particle's flight state.
// F is a Forces<...> functor: Derivative F(x, v, t), LinearisedForces F.linearise(x, v, t).
// The ledger entries (drag dissipation, wind work, per unit mass) are integrated alongside
// x and v by the same method, so the energy residual measures the method's own error.
#pragma once

#include "forces.hpp"

#include <algorithm>
#include <cmath>

namespace pl {

struct FlightState {
    Vec3 x{0.0}, v{0.0};
    double drag_loss = 0.0;  // J/kg dissipated by drag during the step
    double wind_gain = 0.0;  // J/kg of work done by wind during the step
};

struct AdaptiveStats {
    std::uint64_t accepted = 0, rejected = 0;
};

namespace detail {
inline FlightState axpy(const FlightState& y, double h, const Vec3& dx, const Derivative& d) {
    return {y.x + h * dx, y.v + h * d.a, y.drag_loss + h * d.drag_power, y.wind_gain + h * d.wind_power};
}
}  // namespace detail

// Forward (explicit) Euler: x += h v_n, v += h a_n. Order 1; energy grows under gravity.
template <class F>
FlightState explicit_euler_step(const FlightState& y, double t, double h, const F& f) {
    return detail::axpy(y, h, y.v, f(y.x, y.v, t));
}

// Semi-implicit (symplectic) Euler: v += h a_n, x += h v_{n+1}. Order 1.
template <class F>
FlightState semi_implicit_euler_step(const FlightState& y, double t, double h, const F& f) {
    const Derivative d = f(y.x, y.v, t);
    FlightState out{y.x, y.v + h * d.a, y.drag_loss + h * d.drag_power, y.wind_gain + h * d.wind_power};
    out.x = y.x + h * out.v;
    return out;
}

// Velocity Verlet; with velocity-dependent forces the end acceleration uses the Euler-predicted
// velocity (Heun for v), keeping order 2.
template <class F>
FlightState velocity_verlet_step(const FlightState& y, double t, double h, const F& f) {
    const Derivative d0 = f(y.x, y.v, t);
    FlightState out;
    out.x = y.x + h * y.v + (0.5 * h * h) * d0.a;
    const Derivative d1 = f(out.x, y.v + h * d0.a, t + h);
    out.v = y.v + (0.5 * h) * (d0.a + d1.a);
    out.drag_loss = y.drag_loss + 0.5 * h * (d0.drag_power + d1.drag_power);
    out.wind_gain = y.wind_gain + 0.5 * h * (d0.wind_power + d1.wind_power);
    return out;
}

// Classic fourth-order Runge-Kutta.
template <class F>
FlightState rk4_step(const FlightState& y, double t, double h, const F& f) {
    const Derivative k1 = f(y.x, y.v, t);
    const Vec3 x2 = y.x + 0.5 * h * y.v, v2 = y.v + 0.5 * h * k1.a;
    const Derivative k2 = f(x2, v2, t + 0.5 * h);
    const Vec3 x3 = y.x + 0.5 * h * v2, v3 = y.v + 0.5 * h * k2.a;
    const Derivative k3 = f(x3, v3, t + 0.5 * h);
    const Vec3 x4 = y.x + h * v3, v4 = y.v + h * k3.a;
    const Derivative k4 = f(x4, v4, t + h);
    const double s = h / 6.0;
    FlightState out;
    out.x = y.x + s * (y.v + 2.0 * v2 + 2.0 * v3 + v4);
    out.v = y.v + s * (k1.a + 2.0 * k2.a + 2.0 * k3.a + k4.a);
    out.drag_loss = y.drag_loss + s * (k1.drag_power + 2.0 * k2.drag_power + 2.0 * k3.drag_power + k4.drag_power);
    out.wind_gain = y.wind_gain + s * (k1.wind_power + 2.0 * k2.wind_power + 2.0 * k3.wind_power + k4.wind_power);
    return out;
}

// Exponential (drag-exact) step: a = g - k (v - w) with k, w frozen at the step start, solved
// exactly, so it is stable for any h k (Hochbruck & Ostermann, Acta Numerica 2010, exponential
// Euler). Exact for linear drag in constant wind; order 1 for nonlinear drag.
//   v(h) = e^{-kh} v + phi1 (g + k w),   x(h) = x + phi1 v + phi2 (g + k w)
//   phi1 = (1 - e^{-kh}) / k,  phi2 = (kh - 1 + e^{-kh}) / k^2   (-> h, h^2/2 as k -> 0)
template <class F>
FlightState exponential_step(const FlightState& y, double t, double h, const F& f) {
    const LinearisedForces lin = f.linearise(y.x, y.v, t);
    ++f.gravity_evals;
    const double k = lin.k, z = k * h;
    double e, phi1, phi2;
    if (z < 1e-4) {  // Taylor series: avoids cancellation in phi2
        e = std::exp(-z);
        phi1 = h * (1.0 - z / 2.0 + z * z / 6.0 - z * z * z / 24.0);
        phi2 = h * h * (0.5 - z / 6.0 + z * z / 24.0 - z * z * z / 120.0);
    } else {
        e = std::exp(-z);
        phi1 = -std::expm1(-z) / k;
        phi2 = (z - 1.0 + e) / (k * k);
    }
    const Vec3 forcing = f.gravity + k * lin.wind;
    FlightState out;
    out.v = e * y.v + phi1 * forcing;
    out.x = y.x + phi1 * y.v + phi2 * forcing;
    // Ledger: trapezoid of the (frozen-k) drag power at both ends.
    const Vec3 u0 = y.v - lin.wind, u1 = out.v - lin.wind;
    out.drag_loss = y.drag_loss + 0.5 * h * k * (glm::dot(u0, u0) + glm::dot(u1, u1));
    out.wind_gain = y.wind_gain - 0.5 * h * k * (glm::dot(u0, lin.wind) + glm::dot(u1, lin.wind));
    return out;
}

// One Dormand-Prince 5(4) step (Dormand & Prince, J. Comp. Appl. Math. 6, 1980); returns the
// 5th-order solution and writes the scaled error norm of the embedded 4th-order difference.
template <class F>
FlightState dopri5_step(const FlightState& y, double t, double h, const F& f, double rtol, double atol,
                        double& err_norm) {
    constexpr double c2 = 1.0 / 5, c3 = 3.0 / 10, c4 = 4.0 / 5, c5 = 8.0 / 9;
    constexpr double a21 = 1.0 / 5;
    constexpr double a31 = 3.0 / 40, a32 = 9.0 / 40;
    constexpr double a41 = 44.0 / 45, a42 = -56.0 / 15, a43 = 32.0 / 9;
    constexpr double a51 = 19372.0 / 6561, a52 = -25360.0 / 2187, a53 = 64448.0 / 6561, a54 = -212.0 / 729;
    constexpr double a61 = 9017.0 / 3168, a62 = -355.0 / 33, a63 = 46732.0 / 5247, a64 = 49.0 / 176,
                     a65 = -5103.0 / 18656;
    constexpr double b1 = 35.0 / 384, b3 = 500.0 / 1113, b4 = 125.0 / 192, b5 = -2187.0 / 6784, b6 = 11.0 / 84;
    // e = b - b*, the difference to the embedded 4th-order weights.
    constexpr double e1 = 71.0 / 57600, e3 = -71.0 / 16695, e4 = 71.0 / 1920, e5 = -17253.0 / 339200,
                     e6 = 22.0 / 525, e7 = -1.0 / 40;

    // Stages for (x, v): dx/dt = v, dv/dt = a.
    const Vec3 X1 = y.x, V1 = y.v;
    const Derivative K1 = f(X1, V1, t);
    const Vec3 X2 = y.x + h * (a21 * V1), V2 = y.v + h * (a21 * K1.a);
    const Derivative K2 = f(X2, V2, t + c2 * h);
    const Vec3 X3 = y.x + h * (a31 * V1 + a32 * V2), V3 = y.v + h * (a31 * K1.a + a32 * K2.a);
    const Derivative K3 = f(X3, V3, t + c3 * h);
    const Vec3 X4 = y.x + h * (a41 * V1 + a42 * V2 + a43 * V3), V4 = y.v + h * (a41 * K1.a + a42 * K2.a + a43 * K3.a);
    const Derivative K4 = f(X4, V4, t + c4 * h);
    const Vec3 X5 = y.x + h * (a51 * V1 + a52 * V2 + a53 * V3 + a54 * V4),
               V5 = y.v + h * (a51 * K1.a + a52 * K2.a + a53 * K3.a + a54 * K4.a);
    const Derivative K5 = f(X5, V5, t + c5 * h);
    const Vec3 X6 = y.x + h * (a61 * V1 + a62 * V2 + a63 * V3 + a64 * V4 + a65 * V5),
               V6 = y.v + h * (a61 * K1.a + a62 * K2.a + a63 * K3.a + a64 * K4.a + a65 * K5.a);
    const Derivative K6 = f(X6, V6, t + h);
    FlightState out;
    out.x = y.x + h * (b1 * V1 + b3 * V3 + b4 * V4 + b5 * V5 + b6 * V6);
    out.v = y.v + h * (b1 * K1.a + b3 * K3.a + b4 * K4.a + b5 * K5.a + b6 * K6.a);
    out.drag_loss = y.drag_loss + h * (b1 * K1.drag_power + b3 * K3.drag_power + b4 * K4.drag_power +
                                       b5 * K5.drag_power + b6 * K6.drag_power);
    out.wind_gain = y.wind_gain + h * (b1 * K1.wind_power + b3 * K3.wind_power + b4 * K4.wind_power +
                                       b5 * K5.wind_power + b6 * K6.wind_power);
    // 7th stage at the new point (FSAL in a full implementation) for the error estimate.
    const Derivative K7 = f(out.x, out.v, t + h);
    const Vec3 ex = h * (e1 * V1 + e3 * V3 + e4 * V4 + e5 * V5 + e6 * V6 + e7 * out.v);
    const Vec3 ev = h * (e1 * K1.a + e3 * K3.a + e4 * K4.a + e5 * K5.a + e6 * K6.a + e7 * K7.a);
    double norm = 0.0;
    for (int i = 0; i < 3; ++i) {
        norm = std::max(norm, std::abs(ex[i]) / (atol + rtol * std::max(std::abs(y.x[i]), std::abs(out.x[i]))));
        norm = std::max(norm, std::abs(ev[i]) / (atol + rtol * std::max(std::abs(y.v[i]), std::abs(out.v[i]))));
    }
    err_norm = norm;
    return out;
}

// Adaptive Dormand-Prince over [t, t + h]: as many internal steps as the tolerance needs
// (Hairer, Norsett & Wanner, Solving ODEs I, II.4: step-size control with safety 0.9,
// factor limits 0.2..5). `hint` carries the last good internal step between calls.
template <class F>
FlightState dopri5_adaptive(const FlightState& y0, double t, double h, const F& f, double rtol, double atol,
                            double& hint, AdaptiveStats& stats) {
    FlightState y = y0;
    double done = 0.0;
    double step = (hint > 0.0 && hint < h) ? hint : h;
    int guard = 0;
    while (done < h && guard++ < 100000) {
        const bool last = step >= h - done;
        const double s = last ? h - done : step;
        double err = 0.0;
        const FlightState trial = dopri5_step(y, t + done, s, f, rtol, atol, err);
        if (err <= 1.0 || s <= 1e-12 * h) {
            ++stats.accepted;
            y = trial;
            done = last ? h : done + s;
            const double grow = err > 0.0 ? std::min(5.0, 0.9 * std::pow(err, -0.2)) : 5.0;
            if (!last || grow < 1.0) step = s * grow;  // keep the unclipped step across calls
            else step = std::max(step, s * grow);
        } else {
            ++stats.rejected;
            step = s * std::max(0.2, 0.9 * std::pow(err, -0.2));
        }
    }
    hint = step;
    return y;
}

}  // namespace pl
