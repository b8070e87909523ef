// Particle-particle collisions (physics/collide/) against closed forms: 1D impacts with any
// restitution (with bare masses and with added mass), the equal-mass elastic glancing impact (paths at 90 degrees), Newton's cradle, a
// head-on pair far faster than the step can resolve by overlap, impacts that interleave in one step
// (resolved in time order), a struck ball's wall bounce in the same step, the off switch, and the warning
// when a step leaves two balls inside each other.
#include "physics/collide/collision_pass.hpp"
#include "physics/collide/narrow_phase.hpp"
#include "physics/stepping/energy.hpp"
#include "physics/stepping/simulation.hpp"
#include "physics/stepping/warnings.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace pl {
namespace {

// No gravity, no drag, a room far larger than the motion, collisions on.
Model free_space(double restitution, double dt = 1e-3) {
    Model m;
    m.room.size = {100.0, 100.0, 100.0};
    m.world.gravity = {0.0, 0.0, 0.0};
    m.contact.restitution = 1.0;
    m.contact.friction = 0.0;
    m.integrator.dt = dt;
    m.collisions.enabled = true;
    m.collisions.restitution = restitution;
    m.collisions.friction = 0.0;
    return m;
}

ParticleSpec ball(Vec3 x, Vec3 v, double mass, double radius) { return {x, v, mass, radius}; }

// v1' = ((m1 - e m2) v1 + (1 + e) m2 v2) / (m1 + m2), v2' = ((m2 - e m1) v2 + (1 + e) m1 v1) / (m1 + m2).
TEST(Collision, OneDimensionalImpactClosedForm) {
    const double m1 = 0.2, m2 = 0.5, v1 = 3.0, v2 = -1.0, r1 = 0.1, r2 = 0.15;
    for (const double e : {1.0, 0.7, 0.0}) {
        Simulation sim(free_space(e), {ball({-1, 0, 0}, {v1, 0, 0}, m1, r1), ball({1, 0, 0}, {v2, 0, 0}, m2, r2)});
        sim.run_until(1.0);
        const double u1 = ((m1 - e * m2) * v1 + (1 + e) * m2 * v2) / (m1 + m2);
        const double u2 = ((m2 - e * m1) * v2 + (1 + e) * m1 * v1) / (m1 + m2);
        EXPECT_NEAR(sim.state().vx[0], u1, 1e-12) << "e = " << e;
        EXPECT_NEAR(sim.state().vx[1], u2, 1e-12) << "e = " << e;
        // One impact; at e = 0 the pair then moves on touching, and round-off may close it again.
        if (e > 0) {
            EXPECT_EQ(sim.collisions_total(), 1u);
        }
        // Resolved at the time of impact (gap 2 - 0.25 closed at 4 m/s), not at the step's end.
        const double t_hit = (2.0 - r1 - r2) / (v1 - v2);
        const double x_hit = -1.0 + v1 * t_hit;
        EXPECT_NEAR(sim.state().x[0], x_hit + u1 * (sim.time() - t_hit), 1e-9) << "e = " << e;
        EXPECT_NEAR(m1 * sim.state().vx[0] + m2 * sim.state().vx[1], m1 * v1 + m2 * v2, 1e-14);
        const EnergyBreakdown en = total_energy(sim.state(), sim.model().world.gravity, sim.model().room);
        const double lost = 0.5 * m1 * m2 / (m1 + m2) * (1 - e * e) * (v1 - v2) * (v1 - v2);
        EXPECT_NEAR(-en.collision_work, lost, 1e-12) << "e = " << e;
        EXPECT_NEAR(en.residual(), 0.0, 1e-12);
    }
}

TEST(Collision, ImpactWithAddedMassUsesTheInertialMasses) {
    // Balls in a dense fluid (rho = 1000 kg/m^3) carry M = m + 1/2 rho V along: the impact is the
    // closed form above with M for m, M v is conserved, and the ledger (kinetic energy 1/2 M v^2)
    // closes. With the bare masses the second ball would leave at 1.29 m/s instead of 1.44.
    const double m1 = 0.2, m2 = 0.5, v1 = 3.0, v2 = -1.0, r1 = 0.04, r2 = 0.05, rho = 1000.0;
    const double big1 = m1 + 0.5 * rho * (4.0 / 3.0) * std::numbers::pi * r1 * r1 * r1;
    const double big2 = m2 + 0.5 * rho * (4.0 / 3.0) * std::numbers::pi * r2 * r2 * r2;
    for (const double e : {1.0, 0.6}) {
        Model m = free_space(e);
        m.world.air.density_kg_m3 = rho;
        m.world.added_mass = true;
        Simulation sim(m, {ball({-1, 0, 0}, {v1, 0, 0}, m1, r1), ball({1, 0, 0}, {v2, 0, 0}, m2, r2)});
        sim.run_until(1.0);
        const double u1 = ((big1 - e * big2) * v1 + (1 + e) * big2 * v2) / (big1 + big2);
        const double u2 = ((big2 - e * big1) * v2 + (1 + e) * big1 * v1) / (big1 + big2);
        EXPECT_NEAR(sim.state().vx[0], u1, 1e-12) << "e = " << e;
        EXPECT_NEAR(sim.state().vx[1], u2, 1e-12) << "e = " << e;
        EXPECT_NEAR(big1 * sim.state().vx[0] + big2 * sim.state().vx[1], big1 * v1 + big2 * v2, 1e-13);
        const EnergyBreakdown en = total_energy(sim.state(), sim.model().world.gravity, sim.model().room);
        const double lost = 0.5 * big1 * big2 / (big1 + big2) * (1 - e * e) * (v1 - v2) * (v1 - v2);
        EXPECT_NEAR(-en.collision_work, lost, 1e-12) << "e = " << e;
        EXPECT_NEAR(en.residual(), 0.0, 1e-12) << "e = " << e;
    }
}

TEST(Collision, EqualMassElasticGlancingPathsAtRightAngles) {
    const double r = 0.05, impact_parameter = 0.06;  // sin(theta) = b / (2 r)
    Simulation sim(free_space(1.0),
                   {ball({-1, impact_parameter, 0}, {2, 0, 0}, 0.1, r), ball({0, 0, 0}, {0, 0, 0}, 0.1, r)});
    sim.run_until(1.0);
    const Vec3 a = sim.state().velocity(0), b = sim.state().velocity(1);
    EXPECT_NEAR(glm::dot(a, b) / (glm::length(a) * glm::length(b)), 0.0, 1e-12);
    EXPECT_NEAR(glm::dot(a, a) + glm::dot(b, b), 4.0, 1e-12);
    // The struck ball leaves along the line of centres at contact: angle asin(b / 2r) below x.
    EXPECT_NEAR(std::atan2(-b.y, b.x), std::asin(impact_parameter / (2 * r)), 1e-12);
}

TEST(Collision, NewtonsCradleOneBallOutTheOthersStill) {
    const double r = 0.05;
    std::vector<ParticleSpec> balls;
    for (int i = 0; i < 5; ++i) balls.push_back(ball({2 * r * i, 0, 0}, {0, 0, 0}, 0.1, r));
    balls.insert(balls.begin(), ball({-1.0, 0, 0}, {1.5, 0, 0}, 0.1, r));  // the striker
    Simulation sim(free_space(1.0), balls);
    sim.run_until(1.0);
    for (std::size_t i = 0; i + 1 < balls.size(); ++i) EXPECT_NEAR(glm::length(sim.state().velocity(i)), 0.0, 1e-12) << i;
    EXPECT_NEAR(sim.state().vx[5], 1.5, 1e-12);
    EXPECT_EQ(sim.collisions_total(), 5u);
}

TEST(Collision, FastHeadOnPairDoesNotPassThrough) {
    // 1000 m/s each way, dt = 10 ms: 20 m of closing per step against 0.1 m of diameters.
    for (const bool enabled : {true, false}) {
        Model m = free_space(1.0, 0.01);
        m.collisions.enabled = enabled;
        Simulation sim(m, {ball({-1, 0, 0}, {1000, 0, 0}, 0.1, 0.05), ball({1, 0, 0}, {-1000, 0, 0}, 0.1, 0.05)});
        sim.step();
        const bool crossed = sim.state().x[0] > sim.state().x[1];
        EXPECT_EQ(crossed, !enabled);
        if (enabled) {
            EXPECT_DOUBLE_EQ(sim.state().vx[0], -1000.0);
            EXPECT_DOUBLE_EQ(sim.state().vx[1], 1000.0);
            // Contact after (2 - 0.1) / 2000 s = 0.95 ms at x = -0.05, then 9.05 ms back at 1000 m/s.
            const double t_hit = 1.9 / 2000.0;
            EXPECT_NEAR(sim.state().x[0], -1.0 + 1000.0 * t_hit - 1000.0 * (0.01 - t_hit), 1e-9);
        }
    }
}

// Four equal balls on a line, e = 1, one step of 9.5 ms: A strikes B at 1 ms and B passes the
// blow to C, which touches it; C meets the oncoming D at 5 ms, runs back into B at 9 ms, and B
// passes that blow to A. Each impact swaps the velocities. Taking the first contacts on the
// unbent paths first ((A, B) at 1 ms, and (C, D) at 9 ms, C still at rest), B's blow reached C
// only after C had turned back at 9 ms, the two 40% inside each other: in the order of their
// times, every ball ends where the closed form puts it.
TEST(Collision, ImpactsInOneStepAreResolvedInTheOrderOfTheirTimes) {
    const double r = 0.1, v = 10.0, dt = 0.0095;
    Model m = free_space(1.0, dt);
    m.room.size = {20.0, 20.0, 20.0};
    Simulation sim(m, {ball({0.0, 0, 0}, {v, 0, 0}, 1.0, r), ball({0.21, 0, 0}, {0, 0, 0}, 1.0, r),
                       ball({0.41, 0, 0}, {0, 0, 0}, 1.0, r), ball({0.70, 0, 0}, {-v, 0, 0}, 1.0, r)});
    sim.step();
    const ParticleState& s = sim.state();
    const double x[4] = {0.01 - v * (dt - 0.009), 0.21, 0.41, 0.65 + v * (dt - 0.005)};
    const double vx[4] = {-v, 0.0, 0.0, v};
    for (std::size_t i = 0; i < 4; ++i) {
        EXPECT_NEAR(s.x[i], x[i], 1e-9) << i;
        EXPECT_NEAR(s.vx[i], vx[i], 1e-9) << i;
    }
    EXPECT_EQ(sim.collisions_total(), 5u);
    EXPECT_TRUE(sim.collision_pass()->deep_overlaps().empty());
}

TEST(Collision, OffByDefaultParticlesPassThrough) {
    Model m = free_space(1.0);
    m.collisions = CollisionSettings{};
    EXPECT_FALSE(m.collisions.enabled);
    Simulation sim(m, {ball({-1, 0, 0}, {3, 0, 0}, 0.1, 0.1), ball({1, 0, 0}, {-3, 0, 0}, 0.1, 0.1)});
    sim.run_until(1.0);
    EXPECT_GT(sim.state().x[0], sim.state().x[1]);
    EXPECT_EQ(sim.collisions_total(), 0u);
    EXPECT_TRUE(sim.state().collision_work.empty());  // nothing allocated for collisions
}

TEST(Collision, RestingBallStruckOnTheFloorMoves) {
    Model m = free_space(1.0);
    m.world.gravity = {0, -9.81, 0};
    m.room = {{0, 1, 0}, {4, 2, 4}};
    m.contact.rest_speed = 0.05;
    const double r = 0.05;
    Simulation sim(m, {ball({0.5, r, 0}, {0, 0, 0}, 0.1, r), ball({-0.5, r, 0}, {0, 0, 0}, 0.1, r)});
    sim.run_until(0.2);
    ASSERT_TRUE(sim.state().resting[0] & (1u << y_min));
    sim.set_velocity(1, {2, 0, 0});
    sim.run_until(1.0);
    EXPECT_GT(sim.state().x[0], 0.5 + 0.5);  // it was struck after ~0.45 s and slides at 2 m/s
    EXPECT_NEAR(sim.state().vx[0], 2.0, 1e-9);
    EXPECT_NEAR(sim.state().vx[1], 0.0, 1e-9);
}


// A small ball sliding on the floor strikes a big resting one low: the normal at the contact
// points up, so the big ball leaves the floor, and the small one is driven into it and bounces
// off within the same step. Equal masses, e = 1, no friction: the big ball takes the small one's
// velocity along the normal, n = (sqrt(R^2 - (r2 - r1)^2), r2 - r1) / R with R = r1 + r2.
// Before, the pass took the big ball's upward velocity away (it was resting on the floor) and
// left it gliding 2 mm above the floor at the rest of the speed.
TEST(Collision, ABigBallStruckLowLeavesTheFloorAndTheSmallOneBouncesInTheStep) {
    Model m = free_space(1.0);
    m.world.gravity = {0, -9.81, 0};
    m.room = {{0, 1, 0}, {4, 2, 4}};
    m.contact.restitution = 0.5;
    m.contact.rest_speed = 0.05;
    const double big = 0.1, small = 0.02, v = 5.0;
    Simulation sim(m, {ball({0, big, 0}, {0, 0, 0}, 1.0, big), ball({-1, small, 0}, {v, 0, 0}, 1.0, small)});
    sim.run_until(0.17);
    ASSERT_TRUE(sim.state().resting[0] & (1u << y_min));
    sim.run_until(0.2);  // struck at about 0.182 s
    const double reach = big + small, rise = big - small;
    const Vec3 n(std::sqrt(reach * reach - rise * rise) / reach, rise / reach, 0.0);
    const Vec3 out = v * n.x * n;  // along the normal: all of the small ball's normal velocity
    EXPECT_EQ(sim.state().resting[0], 0) << "it left the floor";
    EXPECT_NEAR(sim.state().vx[0], out.x, 1e-9);
    EXPECT_GT(sim.state().y[0], big + 0.03);
    std::vector<Event> bounces, lifts;
    for (const Event& e : sim.events()) {
        if (e.kind == EventKind::bounce && e.particle == 1) bounces.push_back(e);
        if (e.kind == EventKind::lift && e.particle == 0) lifts.push_back(e);
    }
    ASSERT_EQ(lifts.size(), 1u);
    EXPECT_NEAR(lifts[0].speed_out, glm::length(out), 1e-9);
    // The small ball's bounce off the floor inside the step: in at (v - out), out with the
    // floor's e = 0.5 on the normal speed.
    ASSERT_EQ(bounces.size(), 1u);
    const Vec3 in = Vec3(v, 0, 0) - out;
    EXPECT_NEAR(bounces[0].speed_in, glm::length(in), 1e-9);
    EXPECT_NEAR(bounces[0].speed_out, glm::length(Vec3(in.x, -0.5 * in.y, 0.0)), 1e-9);
    EXPECT_GT(bounces[0].t, 0.18);
    EXPECT_LT(bounces[0].t, lifts[0].t);
    // The ledger still balances: the floor's share went to the bounce line.
    const EnergyBreakdown en = total_energy(sim.state(), m.world.gravity, m.room);
    EXPECT_NEAR(en.dissipated_bounce, 0.5 * 1.0 * 0.75 * in.y * in.y, 1e-9);
    EXPECT_LT(std::abs(en.residual()), 1e-3 * en.initial);
}

// A ball struck toward a near wall meets it within the step: A strikes B at 1 ms, B reaches the
// wall 5 cm away at 6 ms and bounces (e = 1), and ends the 10 ms step 4 cm back from the wall,
// moving away. Before, B was held against the wall at the step's end, still moving into it, and
// bounced a step late.
TEST(Collision, ABallStruckTowardAWallBouncesOffItInTheSameStep) {
    const double r = 0.1, v = 10.0, dt = 0.01, wall = 10.0;
    Model m = free_space(1.0, dt);
    m.room.size = {2 * wall, 2 * wall, 2 * wall};
    const double xb = wall - r - 0.05, xa = xb - 2 * r - 0.01;
    Simulation sim(m, {ball({xa, 0, 0}, {v, 0, 0}, 1.0, r), ball({xb, 0, 0}, {0, 0, 0}, 1.0, r)});
    sim.step();
    const ParticleState& s = sim.state();
    EXPECT_NEAR(s.x[0], xa + 0.01, 1e-9);
    EXPECT_NEAR(s.vx[0], 0.0, 1e-9);
    EXPECT_NEAR(s.x[1], wall - r - v * (dt - 0.006), 1e-9);
    EXPECT_NEAR(s.vx[1], -v, 1e-9);
    ASSERT_EQ(sim.events().size(), 1u);
    EXPECT_EQ(sim.events()[0].kind, EventKind::bounce);
    EXPECT_EQ(sim.events()[0].particle, 1u);
    EXPECT_NEAR(sim.events()[0].t, 0.006, 1e-9);
}

// Two balls whose centres coincide have no normal between them. They must still be opened, as
// any overlap is: along "up" (against gravity, +y without it), the lower index below, by the
// overlap pass alone (positions, inverse-mass weighted: the centre of mass stays put, no
// velocity appears). Before, the pass skipped them and they stayed one inside the other.
TEST(Collision, ConcentricBallsAreOpenedAgainstGravity) {
    for (const Vec3 g : {Vec3(0.0), Vec3(9.81, 0, 0)}) {
        Model m = free_space(0.5);
        m.world.gravity = g;
        const double ma = 0.1, mb = 0.3, r = 0.05;
        Simulation sim(m, {ball({0, 0, 0}, {0, 0, 0}, ma, r), ball({0, 0, 0}, {0, 0, 0}, mb, r)});
        sim.run_until(0.05);  // the pair is opened within ~15 steps; gravity moves both alike meanwhile
        const Vec3 d = sim.state().position(1) - sim.state().position(0);
        EXPECT_NEAR(glm::length(d), 2 * r, 0.01 * r) << "gravity " << g.x;
        const Vec3 up = g == Vec3(0.0) ? Vec3(0, 1, 0) : -glm::normalize(g);
        EXPECT_NEAR(glm::dot(d, up), glm::length(d), 1e-12) << "opened along up, b above a";
        // The same displacement for both under gravity: relative to the free fall (semi-implicit
        // Euler's, g dt^2 n (n + 1) / 2 after n steps), the centre of mass did not move, and
        // neither ball picked up a relative velocity.
        const Vec3 fall = 0.5 * g * sim.time() * (sim.time() + m.integrator.dt);
        const Vec3 centre = (ma * sim.state().position(0) + mb * sim.state().position(1)) / (ma + mb);
        EXPECT_NEAR(glm::length(centre - fall), 0.0, 1e-9);
        EXPECT_NEAR(glm::length(sim.state().velocity(1) - sim.state().velocity(0)), 0.0, 1e-12);
    }
}

// The pass meets pairs on straight paths from a step's start to its end. A ball that strikes a
// wall and another ball in one step did not move straight: at dt = 5 ms, balls at 100 m/s in a
// 1 m room (half the room a step) end steps inside each other, and the simulation says so. At
// dt = 0.5 ms (5 cm a step, half a radius) nothing is left overlapping, and nothing is said.
TEST(Collision, ABallThatMetAWallAndABallInOneStepIsReportedWhenLeftInside) {
    auto box = [](double dt) {
        Model m = free_space(1.0, dt);
        m.room.size = {1.0, 1.0, 1.0};
        return Simulation(m, {ball({-0.3, 0, 0}, {100, 0, 0}, 1.0, 0.1), ball({0.3, 0.01, 0}, {-37, 0, 0}, 3.0, 0.1)});
    };
    auto overlap_warnings = [](const Simulation& sim) {
        std::size_t n = 0;
        for (const Warning& w : sim.warnings())
            if (w.kind == WarningKind::collision_overlap) {
                ++n;
                EXPECT_GT(w.value, collide::CollisionPass::warn_overlap);
                EXPECT_NE(warning_message(w, sim.model()).find("smaller dt"), std::string::npos);
            }
        return n;
    };
    Simulation coarse = box(5e-3);
    coarse.run_until(2.0);
    EXPECT_GE(overlap_warnings(coarse), 1u);
    Simulation fine = box(5e-4);
    fine.run_until(2.0);
    EXPECT_EQ(overlap_warnings(fine), 0u);
    EXPECT_GT(fine.collisions_total(), 50u);
}

}  // namespace
}  // namespace pl
