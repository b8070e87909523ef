#include "physics/model/drag.hpp"

#include "physics/model/terms/drag_linear.hpp"
#include "physics/model/terms/drag_quadratic.hpp"
#include "physics/model/terms/drag_sphere_re.hpp"

#include <cmath>
#include <numbers>

namespace pl {

DragCoefficients drag_coefficients(const DragSettings& drag, const Air& air, double mass, double radius) {
    const double pi = std::numbers::pi;
    DragCoefficients c;
    c.re_scale = 2.0 * radius * air.density_kg_m3 / air.viscosity_pa_s;
    switch (drag.model) {
        case DragModel::none: break;
        case DragModel::linear: {
            const double b = drag.linear_b ? *drag.linear_b : 6.0 * pi * air.viscosity_pa_s * radius;  // Stokes
            c.k = b / mass;
            break;
        }
        case DragModel::quadratic:
            c.k = 0.5 * air.density_kg_m3 * drag.cd * pi * radius * radius / mass;
            break;
        case DragModel::sphere_re:
            c.k = pi * radius * air.viscosity_pa_s / (4.0 * mass);
            break;
    }
    return c;
}

double sphere_cd_times_re(double re) {
    if (re <= 0.0) return 24.0;
    const double a = re / 5.0;
    const double b = re / 2.63e5;
    const double c = re / 1.0e6;
    const double cd_rest = 2.6 * a / (1.0 + std::pow(a, 1.52)) +
                           0.411 * std::pow(b, -7.94) / (1.0 + std::pow(b, -8.0)) + 0.25 * c / (1.0 + c);
    return 24.0 + re * cd_rest;
}

double sphere_cd(double re) { return sphere_cd_times_re(re) / re; }

ReRange drag_validity(DragModel model) {
    switch (model) {
        case DragModel::none: return {0.0, INFINITY};
        case DragModel::linear: return {0.0, 1.0};          // Stokes flow
        case DragModel::quadratic: return {1.0e3, 2.0e5};   // Newton regime, constant Cd
        case DragModel::sphere_re: return {0.0, 1.0e6};     // range of the correlation's data
    }
    return {0.0, INFINITY};
}

double drag_stiffness(DragModel model, const DragCoefficients& c, double u) {
    switch (model) {
        case DragModel::none: return 0.0;
        case DragModel::linear: return terms::DragLinear::stiffness(c.k, c.re_scale, u);
        case DragModel::quadratic: return terms::DragQuadratic::stiffness(c.k, c.re_scale, u);
        case DragModel::sphere_re: return terms::DragSphereRe::stiffness(c.k, c.re_scale, u);
    }
    return 0.0;
}

namespace {

template <class Term>
double rate_of(const DragCoefficients& c, double u) {
    Term term;
    term.drag = c;
    return term.rate(Vec3(u, 0.0, 0.0));
}

}  // namespace

double drag_rate(DragModel model, const DragCoefficients& c, double u) {
    switch (model) {
        case DragModel::none: return 0.0;
        case DragModel::linear: return rate_of<terms::DragLinear>(c, u);
        case DragModel::quadratic: return rate_of<terms::DragQuadratic>(c, u);
        case DragModel::sphere_re: return rate_of<terms::DragSphereRe>(c, u);
    }
    return 0.0;
}

}  // namespace pl
