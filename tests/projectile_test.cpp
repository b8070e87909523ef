// Flight without walls against the closed form x(t) = x0 + v0 t + g t^2 / 2.
#include "physics/stepping/simulation.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace pl {
namespace {

Model open_air(Method method, double dt) {
    Model m;
    m.room.size = Vec3(1e6);  // walls far away
    m.integrator.method = method;
    m.integrator.dt = dt;
    return m;
}

Vec3 exact_position(const ParticleSpec& p, const Vec3& g, double t) { return p.position + p.velocity * t + 0.5 * g * t * t; }

TEST(Projectile, SemiImplicitEulerHasItsKnownFirstOrderOffset) {
    // Semi-implicit Euler under constant g: x_n = x0 + v0 t + g t^2/2 + g h t/2 exactly.
    const double h = 0.01;
    ParticleSpec p{{0, 0, 0}, {3, 4, 1}, 1.0, 0.1};
    Simulation sim(open_air(Method::semi_implicit_euler, h), {p});
    sim.step_n(100);
    const double t = sim.time();
    const Vec3 g = sim.model().world.gravity;
    const Vec3 expected = exact_position(p, g, t) + 0.5 * g * h * t;
    EXPECT_NEAR(sim.state().x[0], expected.x, 1e-9);
    EXPECT_NEAR(sim.state().y[0], expected.y, 1e-9);
    EXPECT_NEAR(sim.state().z[0], expected.z, 1e-9);
}

TEST(Projectile, SemiImplicitEulerConvergesAtFirstOrder) {
    ParticleSpec p{{0, 0, 0}, {3, 4, 1}, 1.0, 0.1};
    double previous = 0;
    for (double h : {0.02, 0.01, 0.005}) {
        Simulation sim(open_air(Method::semi_implicit_euler, h), {p});
        sim.run_until(1.0);
        const double err = glm::length(sim.state().position(0) - exact_position(p, sim.model().world.gravity, 1.0));
        if (previous > 0) {
            EXPECT_NEAR(previous / err, 2.0, 0.05);
        }
        previous = err;
    }
}

TEST(Projectile, SecondOrderAndHigherMethodsAreExactForConstantGravity) {
    ParticleSpec p{{0, 0, 0}, {3, 4, 1}, 1.0, 0.1};
    for (Method m : {Method::velocity_verlet, Method::rk4, Method::dopri5, Method::exponential}) {
        Simulation sim(open_air(m, 0.05), {p});
        sim.run_until(2.0);
        const Vec3 expected = exact_position(p, sim.model().world.gravity, 2.0);
        EXPECT_LT(glm::length(sim.state().position(0) - expected), 1e-9) << to_string(m);
    }
}

}  // namespace
}  // namespace pl
