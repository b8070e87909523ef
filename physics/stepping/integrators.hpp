// One step of each integration method for a single particle's flight state.
// F is a Forces<Terms...> functor: Derivative F(x, v, t), LinearisedForces F.linearise(x, v, t).
// The ledger entries (drag dissipation, wind work, per unit mass) are integrated alongside
// x and v by the same method, so the energy residual measures the method's own error.
#pragma once

#include "physics/model/forces.hpp"

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
    const Vec3 forcing = lin.body + k * lin.wind;
    FlightState out;
    out.v = e * y.v + phi1 * forcing;
    out.x = y.x + phi1 * y.v + phi2 * forcing;
    // Ledger: trapezoid of the (frozen-k) drag power at both ends, per kg of m (the air column's
    // k is per kg of the inertial mass: forces.hpp, LinearisedForces).
    double k_ledger = k;
    if constexpr (F::has_air_column) k_ledger = k / lin.inertia_scale;
    const Vec3 u0 = y.v - lin.wind, u1 = out.v - lin.wind;
    out.drag_loss = y.drag_loss + 0.5 * h * k_ledger * (glm::dot(u0, u0) + glm::dot(u1, u1));
    out.wind_gain = y.wind_gain - 0.5 * h * k_ledger * (glm::dot(u0, lin.wind) + glm::dot(u1, lin.wind));
    // The constant body terms' work (buoyancy), by the same trapezoid.
    if constexpr (F::has_extra_body)
        out.wind_gain += 0.5 * h * (glm::dot(lin.extra, y.v) + glm::dot(lin.extra, out.v));
    return out;
}

namespace detail {
// Flight states form a vector space; the Dormand-Prince stages are combinations of them.
inline FlightState operator+(const FlightState& a, const FlightState& b) {
    return {a.x + b.x, a.v + b.v, a.drag_loss + b.drag_loss, a.wind_gain + b.wind_gain};
}
inline FlightState operator-(const FlightState& a, const FlightState& b) {
    return {a.x - b.x, a.v - b.v, a.drag_loss - b.drag_loss, a.wind_gain - b.wind_gain};
}
inline FlightState operator*(double s, const FlightState& a) {
    return {s * a.x, s * a.v, s * a.drag_loss, s * a.wind_gain};
}
// d/dt of the flight state at a stage: (v, a, drag power, wind power).
inline FlightState rate(const Vec3& v, const Derivative& d) { return {v, d.a, d.drag_power, d.wind_power}; }
}  // namespace detail

// One Dormand-Prince 5(4) step (Dormand & Prince, J. Comp. Appl. Math. 6, 1980) with its error
// estimate and the 4th-order continuous extension used to locate wall impacts inside the step
// (Hairer, Norsett & Wanner, Solving ODEs I, II.6, the dense output of DOPRI5).
struct DopriStep {
    FlightState y1;
    double err_norm = 0.0;
    FlightState r1, r2, r3, r4, r5;  // dense output coefficients
    // State at y(t + theta h), theta in [0, 1].
    FlightState at(double theta) const {
        using namespace detail;
        const double u = 1.0 - theta;
        return r1 + theta * (r2 + u * (r3 + theta * (r4 + u * r5)));
    }
};

// Flattened: the seven force evaluations are inlined into the step. Left to its heuristics, GCC
// kept them as calls after unrelated changes elsewhere in fast_kernel.cpp (measured: the whole
// Dormand-Prince particle-step 20% slower).
template <class F>
[[gnu::flatten]] DopriStep dopri5_step(const FlightState& y, double t, double h, const F& f, double rtol,
                                       double atol) {
    using namespace detail;
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
    // Dense output weights (Hairer's DOPRI5, subroutine CONTD5).
    constexpr double d1 = -12715105075.0 / 11282082432.0, d3 = 87487479700.0 / 32700410799.0,
                     d4 = -10690763975.0 / 1880347072.0, d5 = 701980252875.0 / 199316789632.0,
                     d6 = -1453857185.0 / 822651844.0, d7 = 69997945.0 / 29380423.0;

    auto stage = [&](const FlightState& ys, double ts) { return rate(ys.v, f(ys.x, ys.v, ts)); };
    const FlightState k1 = stage(y, t);
    const FlightState k2 = stage(y + h * (a21 * k1), t + c2 * h);
    const FlightState k3 = stage(y + h * (a31 * k1 + a32 * k2), t + c3 * h);
    const FlightState k4 = stage(y + h * (a41 * k1 + a42 * k2 + a43 * k3), t + c4 * h);
    const FlightState k5 = stage(y + h * (a51 * k1 + a52 * k2 + a53 * k3 + a54 * k4), t + c5 * h);
    const FlightState k6 = stage(y + h * (a61 * k1 + a62 * k2 + a63 * k3 + a64 * k4 + a65 * k5), t + h);
    DopriStep out;
    out.y1 = y + h * (b1 * k1 + b3 * k3 + b4 * k4 + b5 * k5 + b6 * k6);
    // The 7th stage, at the new point, serves the error estimate and the dense output.
    const FlightState k7 = stage(out.y1, t + h);
    const FlightState err = h * (e1 * k1 + e3 * k3 + e4 * k4 + e5 * k5 + e6 * k6 + e7 * k7);
    double norm = 0.0;
    for (int i = 0; i < 3; ++i) {
        norm = std::max(norm, std::abs(err.x[i]) / (atol + rtol * std::max(std::abs(y.x[i]), std::abs(out.y1.x[i]))));
        norm = std::max(norm, std::abs(err.v[i]) / (atol + rtol * std::max(std::abs(y.v[i]), std::abs(out.y1.v[i]))));
    }
    out.err_norm = norm;
    const FlightState diff = out.y1 - y;
    const FlightState bspl = h * k1 - diff;
    out.r1 = y;
    out.r2 = diff;
    out.r3 = bspl;
    out.r4 = diff - h * k7 - bspl;
    out.r5 = h * (d1 * k1 + d3 * k3 + d4 * k4 + d5 * k5 + d6 * k6 + d7 * k7);
    return out;
}

// Step-size control for the adaptive Dormand-Prince driver (Hairer, Norsett & Wanner, II.4:
// safety 0.9, factor limits 0.2..5).
inline double dopri5_step_factor(double err_norm) {
    if (err_norm <= 0.0) return 5.0;
    return std::clamp(0.9 * std::pow(err_norm, -0.2), 0.2, 5.0);
}

}  // namespace pl
