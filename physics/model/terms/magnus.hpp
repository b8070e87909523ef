// Magnus lift on a spinning sphere (drag.lift; Nathan, "The effect of spin on the flight of a
// baseball", Am. J. Phys. 76, 119 (2008), eq. 1):
//   F = 1/2 rho A C_L(S) |u|^2 (w_hat x u_hat),  u = v - wind,  S = R |w| / |u|,  A = pi R^2,
// per unit mass a = K C_L(S) |u| (w_hat x u), K = 1/2 rho A / m. The force is normal to u, so it
// does no work relative to the air; its work in the ground frame, dot(a, v) (nonzero only in a
// wind), goes to the air_work line. C_L(S), both fitted to baseball data, 0.05 < S < 0.5:
//   sawicki: Sawicki, Hubbard & Stronge, "How to hit home runs", Am. J. Phys. 71, 1152 (2003):
//            C_L = 1.5 S for S <= 0.1, 0.09 + 0.6 S above (bilinear, keeps rising beyond the data);
//   nathan:  the saturating fit of Nathan's trajectory calculator, C_L = 1.120 S / (0.583 + 2.333 S)
//            (tends to 0.48 as S grows, where the linear law overshoots).
// Outside 0.05 < S < 0.5 both are extrapolations: below, the lift of a smooth ball can reverse
// sign near the drag crisis (not modelled); above (a slowly moving, fast-spinning ball), the
// sawicki line overestimates the lift and nathan's saturation is the safer guess.
// Spin decay: the aerodynamic torque slows the spin exponentially, w(t) = w0 exp(-t / tau),
// tau = drag.spin_decay (Nathan's calculator: tau = 30 s at 100 mph; Nathan, "The effect of
// spin-down on the flight of a baseball" (2008): tau ~ 5 s to 50 s with the torque parameter).
// tau is held constant, so w is known in closed form at any time of the step and the (x, v)
// equations keep each method's order; the speed dependence of tau (about 1/|v|) is not modelled.
#pragma once

#include "physics/model/field_schema.hpp"
#include "physics/model/terms/term.hpp"

#include <cmath>
#include <numbers>

namespace pl {

// A particle's spin as a function of time: `omega` at time `since`, decaying at `decay_rate`
// (1/tau; 0 without the aerodynamic torque).
struct SpinClock {
    Vec3 omega{0.0};
    double since = 0.0;
    double decay_rate = 0.0;
    Vec3 at(double t) const { return decay_rate == 0.0 ? omega : std::exp(-(t - since) * decay_rate) * omega; }
};

// C_L(S) of the chosen correlation (see the file comment), S >= 0.
inline double lift_coefficient(LiftModel model, double s) {
    switch (model) {
        case LiftModel::none: return 0.0;
        case LiftModel::sawicki: return s <= 0.1 ? 1.5 * s : 0.09 + 0.6 * s;
        case LiftModel::nathan: return 1.120 * s / (0.583 + 2.333 * s);
    }
    return 0.0;
}

namespace terms {

struct Magnus {
    static constexpr TermRole role = TermRole::lift;
    static constexpr Ledger ledger = Ledger::air_work;
    static constexpr std::uint64_t ForceCounters::*counter = &ForceCounters::magnus;
    static constexpr bool rest_is_uniform = false;
    static bool enabled(const Model& m) { return m.drag.lift != LiftModel::none; }

    double lift_k = 0.0;  // K = 1/2 rho pi R^2 / m, 1/m
    double radius = 0.0;
    LiftModel model = LiftModel::none;
    const SpinClock* spin = nullptr;  // the particle's spin (the stepper updates it at impacts)
    mutable std::uint64_t evals = 0;

    void load(const TermInputs& in) {
        lift_k = 0.5 * in.air_density * std::numbers::pi * in.radius * in.radius / in.mass;
        radius = in.radius;
        model = in.lift;
        spin = in.spin;
    }
    // The lift acceleration at air-relative velocity u and time t (zero without spin or speed).
    Vec3 lift(const Vec3& u, double t) const {
        const Vec3 w = spin->at(t);
        const double w_len = glm::length(w), u_len = glm::length(u);
        if (w_len == 0.0 || u_len == 0.0) return Vec3(0.0);
        const double c_l = lift_coefficient(model, radius * w_len / u_len);
        return (lift_k * c_l * u_len / w_len) * glm::cross(w, u);
    }
};

// Its preset rows, "drag.lift" and "drag.spin_decay" (listed in physics/model/schema/drag_fields.hpp).
inline constexpr schema::Field<DragSettings> lift_row = schema::enumeration<DragSettings, &DragSettings::lift>(
    "lift", 3, "Magnus lift",
    "Lift on spinning particles, F = 1/2 rho A C_L(S) |u|^2 (w x u)/|w x u|, S = R|w|/|u|. none; sawicki: "
    "C_L = 1.5 S below S = 0.1, 0.09 + 0.6 S above (Sawicki et al. 2003); nathan: C_L = 1.12 S / (0.583 + "
    "2.333 S) (Nathan's fit). Both fitted to baseballs for 0.05 < S < 0.5.");
inline constexpr schema::Field<DragSettings> spin_decay_row = schema::number(
    "spin_decay", &DragSettings::spin_decay_s, "s", schema::positive(1e9), "spin decay time",
    "With lift: the aerodynamic torque slows the spin as exp(-t / tau); tau about 30 s for a baseball (Nathan).");

}  // namespace terms
}  // namespace pl
