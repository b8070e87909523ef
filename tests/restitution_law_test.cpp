// Speed-dependent restitution (physics/model/restitution.hpp): each rebound follows e(v_n), the
// faster impacts lose more, and such a scene runs on the generic kernel.
#include "physics/model/restitution.hpp"
#include "physics/stepping/energy.hpp"
#include "physics/stepping/simulation.hpp"
#include "test_scenes.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace pl {
namespace {

ContactSettings viscoelastic(double e_ref, double v_ref) {
    ContactSettings c;
    c.restitution = e_ref;
    c.restitution_law = RestitutionLaw::viscoelastic;
    c.restitution_speed = v_ref;
    c.friction = 0.0;
    c.rest_speed = 1e-3;
    return c;
}

TEST(RestitutionLaw, ViscoelasticLeadingOrder) {
    const ContactSettings c = viscoelastic(0.9, 1.0);
    EXPECT_DOUBLE_EQ(restitution_at(c, 1.0), 0.9);
    EXPECT_NEAR(restitution_at(c, 32.0), 1.0 - 0.1 * 2.0, 1e-15);  // 32^(1/5) = 2
    EXPECT_NEAR(restitution_at(c, 1.0 / 32.0), 0.95, 1e-15);
    EXPECT_EQ(restitution_at(c, 0.0), 1.0);
    EXPECT_EQ(restitution_at(viscoelastic(0.5, 1.0), 1e6), 0.0);  // clamped where the series fails
    ContactSettings constant = c;
    constant.restitution_law = RestitutionLaw::constant;
    EXPECT_EQ(restitution_at(constant, 32.0), 0.9);
}

TEST(RestitutionLaw, EachReboundFollowsTheLawAndSlowerImpactsLoseLess) {
    Model m = test::drop_model(0.9, Method::velocity_verlet, 1e-3);
    m.contact = viscoelastic(0.9, 1.0);
    Simulation sim(m, {test::ball_at_height(1.0)});
    EXPECT_EQ(sim.counters().fast_path, 0u);
    sim.run_until(12.0);  // rests after about 8 s
    EXPECT_EQ(sim.counters().fast_path, 0u);  // routed to the generic kernel
    const std::vector<Event> bounces = test::of_kind(sim.events(), EventKind::bounce);
    ASSERT_GT(bounces.size(), 10u);
    double last_e = 0.0;
    for (const Event& b : bounces) {
        const double e = b.speed_out / b.speed_in;
        EXPECT_NEAR(e, restitution_at(m.contact, b.speed_in), 1e-12) << b.t;
        EXPECT_GT(e, last_e);  // the impacts slow down, e rises
        last_e = e;
    }
    EXPECT_NEAR(bounces.front().speed_out / bounces.front().speed_in,
                1.0 - 0.1 * std::pow(std::sqrt(2.0 * 9.81 * 1.0), 0.2), 1e-9);
    // The rest threshold still ends the tail of ever smaller bounces (see restitution.hpp).
    EXPECT_FALSE(test::of_kind(sim.events(), EventKind::rest).empty());
    const EnergyBreakdown e = total_energy(sim.state(), m.world.gravity, m.room);
    EXPECT_LT(std::abs(e.residual()), 1e-9 * e.initial);
}

}  // namespace
}  // namespace pl
