// The fast kernel (vectorised flight + generic contact) against the generic reference kernel:
// random seeded scenes with many particles bouncing, resting, sliding, under drag and wind,
// must give bit-identical state, ledger, events, warnings and force counts after many steps.
#include "physics/stepping/fast_kernel.hpp"
#include "physics/model/random.hpp"
#include "physics/stepping/simulation.hpp"
#include "same_state.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>

namespace pl {
namespace {

struct Scenario {
    Model model;
    std::vector<ParticleSpec> particles;
};

// A room full of particles: some thrown hard at the walls, some dropped to come to rest.
// identical: every particle has the same mass and radius (the kernel then reads them once).
Scenario random_scenario(std::uint64_t seed, Method method, DragModel drag, WindKind wind, std::size_t n,
                         bool identical = false) {
    SplitMix64 rng(seed);
    Scenario s;
    Model& m = s.model;
    m.room.center = {rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
    m.room.size = {rng.uniform(1.0, 3.0), rng.uniform(1.0, 3.0), rng.uniform(1.0, 3.0)};
    m.contact.restitution = rng.uniform(0.2, 0.9);
    m.contact.friction = rng.uniform(0.1, 0.6);
    m.contact.rest_speed = 0.2;
    m.integrator.method = method;
    m.integrator.dt = 0.004;
    m.drag.model = drag;
    m.drag.cd = 0.47;
    if (drag == DragModel::linear) m.drag.linear_b = rng.uniform(0.001, 0.05);
    m.world.wind.kind = wind;
    m.world.wind.velocity = {rng.uniform(-4, 4), rng.uniform(-1, 1), rng.uniform(-4, 4)};
    m.world.wind.vortex_center = m.room.center;
    const Vec3 lo = m.room.min_corner(), hi = m.room.max_corner();
    const double radius = identical ? rng.uniform(0.01, 0.12) : 0.0;
    const double mass = identical ? rng.uniform(0.005, 0.5) : 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        ParticleSpec p;
        p.radius = identical ? radius : rng.uniform(0.01, 0.12);
        p.mass = identical ? mass : rng.uniform(0.005, 0.5);
        for (int a = 0; a < 3; ++a) p.position[a] = rng.uniform(lo[a] + p.radius, hi[a] - p.radius);
        const double speed = i % 3 == 0 ? 0.0 : rng.uniform(0.0, 12.0);
        p.velocity = speed * Vec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
        s.particles.push_back(p);
    }
    return s;
}

struct Pair {
    Simulation fast, generic;
    Pair(const Scenario& s) : fast(s.model, s.particles), generic(s.model, s.particles) {
        fast.set_threads(1);
        generic.set_kernel(KernelChoice::generic);
    }
    void step_n(int n) {
        fast.step_n(static_cast<std::uint64_t>(n));
        generic.step_n(static_cast<std::uint64_t>(n));
    }
};

std::size_t count_kind(const std::vector<Event>& events, EventKind kind) {
    std::size_t n = 0;
    for (const Event& e : events) n += e.kind == kind;
    return n;
}

const Method all_methods[] = {Method::explicit_euler, Method::semi_implicit_euler, Method::velocity_verlet,
                              Method::rk4,            Method::dopri5,              Method::exponential};
const DragModel all_drags[] = {DragModel::none, DragModel::linear, DragModel::quadratic, DragModel::sphere_re};

TEST(FastKernel, BitIdenticalToGenericForEveryMethodAndDragModel) {
    std::uint64_t seed = 100;
    std::size_t rests = 0;
    for (Method method : all_methods) {
        for (DragModel drag : all_drags) {
            SCOPED_TRACE(std::string(to_string(method)) + " / " + to_string(drag));
            Pair p(random_scenario(++seed, method, drag, WindKind::none, 150));
            p.step_n(400);
            test::expect_identical(p.fast, p.generic);
            // The scenes must exercise the contact path, or the comparison proves little.
            EXPECT_GT(count_kind(p.generic.events(), EventKind::bounce), 50u);
            EXPECT_GT(count_kind(p.generic.events(), EventKind::rest), 0u);
            rests += count_kind(p.generic.events(), EventKind::rest);
        }
    }
    EXPECT_GT(rests, 200u);
}

TEST(FastKernel, BitIdenticalForIdenticalParticles) {
    std::uint64_t seed = 150;
    for (Method method : all_methods) {
        for (DragModel drag : all_drags) {
            SCOPED_TRACE(std::string(to_string(method)) + " / " + to_string(drag));
            Pair p(random_scenario(++seed, method, drag, WindKind::none, 150, true));
            ASSERT_TRUE(p.fast.identical_particles());
            p.step_n(400);
            test::expect_identical(p.fast, p.generic);
            EXPECT_GT(count_kind(p.generic.events(), EventKind::bounce), 50u);
        }
    }
    // Wind, where the wind is looked up before the vector loop.
    Pair wind(random_scenario(++seed, Method::semi_implicit_euler, DragModel::quadratic, WindKind::shear, 150, true));
    wind.step_n(300);
    test::expect_identical(wind.fast, wind.generic);
    Pair mixed(random_scenario(++seed, Method::semi_implicit_euler, DragModel::quadratic, WindKind::none, 10));
    EXPECT_FALSE(mixed.fast.identical_particles());
}

// Beyond cache_resident_particles phase 1 writes whole vectors instead of masked stores and
// reads the held bits by a shift instead of a table, in the first step of a call (the others
// find the block in cache): one step per call after some have come to rest exercises it with
// held particles.
TEST(FastKernel, BitIdenticalWhenTheStateStreamsFromMemory) {
    const std::size_t n = cache_resident_particles + 1000;
    for (const bool identical : {false, true}) {
        SCOPED_TRACE(identical ? "identical particles" : "particles of their own");
        Pair p(random_scenario(identical ? 301 : 302, Method::semi_implicit_euler, DragModel::quadratic,
                               WindKind::none, n, identical));
        p.step_n(12);
        test::expect_identical(p.fast, p.generic);
        EXPECT_GT(count_kind(p.generic.events(), EventKind::bounce), 1000u);
        for (int k = 0; k < 12; ++k) p.step_n(1);
        test::expect_identical(p.fast, p.generic);
    }
}

TEST(FastKernel, BitIdenticalUnderEveryWindKind) {
    std::uint64_t seed = 200;
    for (WindKind wind : {WindKind::constant, WindKind::gust, WindKind::shear, WindKind::vortex}) {
        for (DragModel drag : {DragModel::linear, DragModel::quadratic}) {
            for (Method method : {Method::explicit_euler, Method::semi_implicit_euler, Method::rk4}) {
                SCOPED_TRACE(std::string(to_string(wind)) + " / " + to_string(drag) + " / " + to_string(method));
                Pair p(random_scenario(++seed, method, drag, wind, 80));
                p.step_n(300);
                test::expect_identical(p.fast, p.generic);
                EXPECT_GT(p.generic.counters().wind, 0u);
            }
        }
    }
}

TEST(FastKernel, FlightMethodsFinishMostParticleStepsInTheVectorisedPhase) {
    for (Method method : all_methods) {
        Pair p(random_scenario(7, method, DragModel::quadratic, WindKind::none, 200));
        p.step_n(200);
        const std::uint64_t particle_steps = 200u * 200u;
        if (has_fast_flight(p.fast.model())) {
            EXPECT_GT(p.fast.counters().fast_path, particle_steps / 2) << to_string(method);
            EXPECT_LT(p.fast.counters().fast_path, particle_steps) << to_string(method);
        } else {
            EXPECT_EQ(p.fast.counters().fast_path, 0u) << to_string(method);
        }
        EXPECT_EQ(p.generic.counters().fast_path, 0u);
    }
}

TEST(FastKernel, NonFiniteParticlesFreezeExactlyAsInTheGenericKernel) {
    Scenario s = random_scenario(11, Method::semi_implicit_euler, DragModel::quadratic, WindKind::none, 40);
    s.particles[5].velocity = {1e200, -1e200, 0.0};  // |v|^2 overflows: the drag becomes Inf/NaN
    s.particles[17].velocity = {0.0, 1e300, 0.0};
    Pair p(s);
    p.step_n(50);
    test::expect_identical(p.fast, p.generic);
    EXPECT_EQ(p.generic.state().frozen[5], 1);
    EXPECT_EQ(p.generic.state().frozen[17], 1);
    EXPECT_EQ(count_kind(p.generic.events(), EventKind::frozen), 2u);
}

// Rooms whose particles have come to rest: chunks with many resting particles slide them in
// place (a vector pass) instead of through the contact lanes, and chunks at rest for good are
// skipped, for every method with a closed-form position, with and without friction, wind,
// identical particles, and gravity tilted so that the floor holds them (friction 0.3) or not
// (friction 0.1: they slide on).
TEST(FastKernel, RoomsAtRestStayBitIdentical) {
    struct Case {
        Method method;
        DragModel drag;
        WindKind wind;
        bool identical;
        double friction;
        double tilt = 0.0;  // horizontal gravity, m/s^2
    };
    const Case cases[] = {
        {Method::semi_implicit_euler, DragModel::quadratic, WindKind::none, true, 0.4},
        {Method::semi_implicit_euler, DragModel::quadratic, WindKind::none, false, 0.0},
        {Method::semi_implicit_euler, DragModel::linear, WindKind::constant, false, 0.3},
        {Method::explicit_euler, DragModel::quadratic, WindKind::none, false, 0.5},
        {Method::explicit_euler, DragModel::none, WindKind::none, true, 0.2},
        {Method::velocity_verlet, DragModel::quadratic, WindKind::none, true, 0.3},
        {Method::velocity_verlet, DragModel::sphere_re, WindKind::none, false, 0.3},
        {Method::semi_implicit_euler, DragModel::quadratic, WindKind::none, true, 0.3, 1.5},
        {Method::semi_implicit_euler, DragModel::quadratic, WindKind::none, true, 0.1, 1.5},
        {Method::rk4, DragModel::linear, WindKind::none, true, 0.3, 0.0},
    };
    std::uint64_t seed = 900;
    for (const Case& c : cases) {
        Scenario s = random_scenario(++seed, c.method, c.drag, c.wind, 600, c.identical);
        s.model.contact.friction = c.friction;
        s.model.world.gravity.x = c.tilt;
        s.model.world.wind.velocity *= 0.05;  // a breeze that does not lift them
        Pair p(s);
        p.step_n(1500);
        SCOPED_TRACE(std::string(to_string(c.method)) + " " + to_string(c.drag));
        test::expect_identical(p.fast, p.generic);
        std::size_t resting = 0;
        for (std::uint8_t r : p.generic.state().resting) resting += r != 0;
        EXPECT_GT(resting, 450u);  // most chunks are over the in-place threshold
    }
}

TEST(FastKernel, KicksAndDrainedEventsStayIdentical) {
    Pair p(random_scenario(13, Method::semi_implicit_euler, DragModel::linear, WindKind::none, 120));
    p.step_n(500);  // most particles rest by now
    for (std::size_t i = 0; i < 120; i += 7) {
        const Vec3 kick(0.5, 3.0 + 0.01 * static_cast<double>(i), -0.25);
        p.fast.set_velocity(i, kick);
        p.generic.set_velocity(i, kick);
    }
    EXPECT_TRUE(test::same_events(p.fast.drain_events(), p.generic.drain_events()));
    p.step_n(200);
    test::expect_identical(p.fast, p.generic);
    EXPECT_GT(count_kind(p.generic.events(), EventKind::bounce), 0u);
}

}  // namespace
}  // namespace pl
