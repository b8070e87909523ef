// A Model built in code is checked where the Simulation is constructed: each broken invariant
// gives std::invalid_argument naming the field (before, dt = 0 made steps_to loop forever and a
// particle outside the room was stepped from there). steps_to is closed-form.
#include "physics/stepping/simulation.hpp"
#include "physics/model/random.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>

namespace pl {
namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr double inf = std::numeric_limits<double>::infinity();

struct Broken {
    const char* field;  // the message must start with it
    std::function<void(Model&, ParticleSpec&)> edit;
};

const Broken broken[] = {
    {"integrator.dt", [](Model& m, ParticleSpec&) { m.integrator.dt = 0.0; }},
    {"integrator.dt", [](Model& m, ParticleSpec&) { m.integrator.dt = -1e-3; }},
    {"integrator.dt", [](Model& m, ParticleSpec&) { m.integrator.dt = nan; }},
    {"integrator.dt", [](Model& m, ParticleSpec&) { m.integrator.dt = inf; }},
    {"integrator.rtol", [](Model& m, ParticleSpec&) {
         m.integrator.method = Method::dopri5;
         m.integrator.rtol = 0.0;
     }},
    {"integrator.atol", [](Model& m, ParticleSpec&) {
         m.integrator.method = Method::dopri5;
         m.integrator.atol = -1.0;
     }},
    {"room.size[1]", [](Model& m, ParticleSpec&) { m.room.size.y = 0.0; }},
    {"room.size[0]", [](Model& m, ParticleSpec&) { m.room.size.x = -2.0; }},
    {"room.center", [](Model& m, ParticleSpec&) { m.room.center.z = nan; }},
    {"world.gravity", [](Model& m, ParticleSpec&) { m.world.gravity.y = -inf; }},
    {"world.air.density", [](Model& m, ParticleSpec&) { m.world.air.density_kg_m3 = -1.0; }},
    {"world.wind.velocity", [](Model& m, ParticleSpec&) { m.world.wind.velocity.x = nan; }},
    {"world.wind.period", [](Model& m, ParticleSpec&) {
         m.world.wind.kind = WindKind::gust;
         m.world.wind.gust_period_s = 0.0;
     }},
    {"world.wind.core_radius", [](Model& m, ParticleSpec&) {
         m.world.wind.kind = WindKind::vortex;
         m.world.wind.vortex_core_radius_m = 0.0;
     }},
    {"drag.cd", [](Model& m, ParticleSpec&) { m.drag.cd = nan; }},
    {"drag.b", [](Model& m, ParticleSpec&) { m.drag.linear_b = -0.1; }},
    {"contact.restitution", [](Model& m, ParticleSpec&) { m.contact.restitution = 1.5; }},
    {"contact.friction", [](Model& m, ParticleSpec&) { m.contact.friction = -0.1; }},
    {"particles[0].mass", [](Model&, ParticleSpec& p) { p.mass = 0.0; }},
    {"particles[0].radius", [](Model&, ParticleSpec& p) { p.radius = -0.01; }},
    {"particles[0].velocity", [](Model&, ParticleSpec& p) { p.velocity.y = nan; }},
    {"particles[0].position", [](Model&, ParticleSpec& p) { p.position.x = inf; }},
    {"particles[0].position", [](Model&, ParticleSpec& p) { p.position.y = 100.0; }},     // above the ceiling
    {"particles[0].position", [](Model&, ParticleSpec& p) { p.position.y = -3.0; }},      // sunk into the floor
};

TEST(ModelCheck, EachBrokenInvariantNamesItsField) {
    for (const Broken& b : broken) {
        Model m;
        ParticleSpec p;
        b.edit(m, p);
        try {
            Simulation sim(m, {p});
            ADD_FAILURE() << b.field << ": accepted";
        } catch (const std::invalid_argument& e) {
            EXPECT_EQ(std::string(e.what()).rfind(std::string(b.field) + ": ", 0), 0u) << e.what();
        }
    }
}

TEST(ModelCheck, TheDefaultsAndASphereOnTheFloorAreAccepted) {
    Model m;
    ParticleSpec p;
    p.position.y = m.room.floor_y() + p.radius;
    EXPECT_NO_THROW(Simulation(m, {p}));
    m.integrator.method = Method::dopri5;
    EXPECT_NO_THROW(Simulation(m, {p}));
}

// What steps_to counted one step at a time before it became closed-form.
std::uint64_t counted(std::uint64_t taken, double dt, double t) {
    std::uint64_t k = 0;
    while (static_cast<double>(taken + k + 1) * dt <= t * (1.0 + 1e-12)) ++k;
    return k;
}

TEST(StepsTo, MatchesCountingOneStepAtATime) {
    SplitMix64 rng(5);
    for (int trial = 0; trial < 2000; ++trial) {
        Model m;
        m.integrator.dt = trial % 3 == 0 ? 0.002 : trial % 3 == 1 ? 0.1 / 3.0 : rng.uniform(1e-4, 0.05);
        Simulation sim(m, {ParticleSpec{}});
        const std::uint64_t taken = static_cast<std::uint64_t>(rng.uniform(0.0, 5.0));
        sim.step_n(taken);
        // On the step grid (where rounding decides) and off it.
        const double t = trial % 2 == 0 ? static_cast<double>(static_cast<int>(rng.uniform(0, 300))) * m.integrator.dt
                                        : rng.uniform(-1.0, 10.0);
        EXPECT_EQ(sim.steps_to(t), counted(taken, m.integrator.dt, t)) << "dt " << m.integrator.dt << " t " << t;
    }
}

TEST(StepsTo, FarTimesAreClosedForm) {
    Model m;
    m.integrator.dt = 1e-6;
    const Simulation sim(m, {ParticleSpec{}});
    // 1e12 steps: counted one at a time this took minutes.
    const std::uint64_t n = sim.steps_to(1e6);
    EXPECT_LE(static_cast<double>(n) * 1e-6, 1e6 * (1.0 + 1e-12));
    EXPECT_GT(static_cast<double>(n + 1) * 1e-6, 1e6 * (1.0 + 1e-12));
    EXPECT_THROW((void)sim.steps_to(inf), std::invalid_argument);
    EXPECT_THROW((void)sim.steps_to(nan), std::invalid_argument);
    EXPECT_EQ(sim.steps_to(-inf), 0u);
}

}  // namespace
}  // namespace pl
