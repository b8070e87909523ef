// What a traced step saw on its own trajectory: the located state of each wall impact and the
// highest point of its flight. Only metrics ask for it, by replaying a tracked particle's step
// (step_replay.hpp); the stepping kernels run with StepContext::trace null and record nothing.
//
// "The step's own trajectory" is the one the wall-impact search uses (particle_stepper.hpp):
//  * Euler and Verlet: the position is a polynomial in the step length q, x0 + q u0 + kappa q^2 a0
//    (position_kappa; semi-implicit Euler on the parabola of its true velocity u0 = v0 + a0 s / 2,
//    whose end point at q = s is the step's), so the highest point is the vertex of a quadratic;
//  * RK4, the exponential step and fixed-step Dormand-Prince: the method re-run with a shorter
//    step q; adaptive Dormand-Prince: the dense output of each internal step. The highest point
//    is where the vertical velocity crosses zero, found by the same bracketing root search
//    (find_contact) that locates wall impacts.
#pragma once

#include "physics/model/scene.hpp"

#include <cmath>
#include <vector>

namespace pl {

// Root of d(s) on [0, h], d(h) <= 0: bisection while the lower end is not above 0 (the root
// could be at 0 or later), then Illinois regula falsi (Dahlquist & Bjorck), which converges
// superlinearly. Returns the end of the bracket at or just past the root. Locates wall impacts
// (d: the distance to the wall) and the highest point of a flight (d: the vertical velocity).
template <class Distance>
double find_contact(const Distance& d, double h) {
    double lo = 0.0, hi = h;
    double f_lo = d(lo), f_hi = d(hi);
    int side = 0;
    for (int it = 0; it < 80 && hi - lo > 1e-15 * h; ++it) {
        double s;
        if (f_lo <= 0.0) {
            s = 0.5 * (lo + hi);
        } else {
            s = lo + (hi - lo) * f_lo / (f_lo - f_hi);
            if (!(s > lo && s < hi)) s = 0.5 * (lo + hi);
        }
        const double f_s = d(s);
        if (f_s > 0.0) {
            lo = s;
            f_lo = f_s;
            if (side == -1) f_hi *= 0.5;
            side = -1;
        } else {
            hi = s;
            f_hi = f_s;
            if (side == 1 && f_lo > 0.0) f_lo *= 0.5;
            side = 1;
        }
        if (f_s == 0.0) break;
    }
    return hi;
}

struct StepTrace {
    struct Impact {
        double t;  // the impact event's time
        Vec3 x;    // the located centre position at it (on the wall's contact plane)
    };
    std::vector<Impact> impacts;  // in the order the step met them
    // Highest centre y on the step's flight (interior turning points and impact positions; the
    // step's ends are the caller's to sample), and when; -inf if the step flew no such point.
    double apex_y = -INFINITY;
    double apex_t = 0.0;

    void offer_apex(double t, double y) {
        if (y > apex_y) {
            apex_y = y;
            apex_t = t;
        }
    }
    void impact(double t, const Vec3& x) {
        impacts.push_back({t, x});
        offer_apex(t, x.y);
    }
    // Flight from t over [0, s] whose height is y0 + b q + c q^2: its vertex when it lies inside.
    void quadratic_flight(double t, double s, double y0, double b, double c) {
        if (!(b > 0.0 && c < 0.0)) return;
        const double q = -b / (2.0 * c);
        if (q < s) offer_apex(t + q, y0 + 0.5 * b * q);
    }
    // Flight from t over [0, s] whose state at q is at(q) (a FlightState): where its vertical
    // velocity turns from up to down inside, the height there.
    template <class At>
    void flight(double t, double s, const At& at) {
        if (!(at(0.0).v.y > 0.0 && at(s).v.y <= 0.0)) return;
        const double q = find_contact([&](double r) { return at(r).v.y; }, s);
        offer_apex(t + q, at(q).x.y);
    }
};

}  // namespace pl
