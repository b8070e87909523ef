// Which warnings put a number at risk: constant-Cd drag on a tennis ball just below Re 1e3 is
// negligible next to gravity (a note); Stokes drag on the same ball at Re 5e4 is wrong by far
// more than 1% of gravity (a warning); a Mach warning always counts.
#include "ui/warning_risk.hpp"

#include <gtest/gtest.h>

namespace pl::ui {
namespace {

Simulation tennis_ball(DragModel model) {
    Model m;
    m.drag.model = model;
    return Simulation(m, {ParticleSpec{}});  // 57 g, radius 3.3 cm, sea-level air
}

TEST(WarningRisk, SlowConstantCdDragIsANote) {
    const Simulation sim = tennis_ball(DragModel::quadratic);
    const Warning w{WarningKind::drag_validity, 0, 1.4, 915.0};
    EXPECT_LT(drag_error_fraction(w, sim), 1e-3);
    EXPECT_FALSE(puts_number_at_risk(w, sim));
}

TEST(WarningRisk, StokesDragOnAThrownBallIsAtRisk) {
    const Simulation sim = tennis_ball(DragModel::linear);
    const Warning w{WarningKind::drag_validity, 0, 0.0, 5.05e4};
    EXPECT_GT(drag_error_fraction(w, sim), 0.1);
    EXPECT_TRUE(puts_number_at_risk(w, sim));
}

TEST(WarningRisk, OtherKindsAndBeyondTheReferenceAlwaysCount) {
    const Simulation sim = tennis_ball(DragModel::quadratic);
    EXPECT_TRUE(puts_number_at_risk({WarningKind::mach, 0, 0.0, 200.0}, sim));
    EXPECT_TRUE(puts_number_at_risk({WarningKind::drag_validity, 0, 0.0, 5e6}, sim));
}

}  // namespace
}  // namespace pl::ui
