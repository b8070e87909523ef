// The emitter is one seeded draw sequence: any prefix of it is the same particles, which lets the
// GUI take particle 0 of a two-million-particle scene without building the other 1,999,999.
// Also how tightly emitted balls start (physics/model/start_packing.hpp).
#include "physics/model/emitter.hpp"
#include "physics/model/start_packing.hpp"
#include "physics/model/scene.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace pl {
namespace {

Emitter spray(std::size_t count) {
    Emitter e;
    e.count = count;
    e.seed = 7;
    e.spread_deg = 45;
    return e;
}

bool same(const ParticleSpec& a, const ParticleSpec& b) {
    return a.position == b.position && a.velocity == b.velocity && a.mass == b.mass && a.radius == b.radius;
}

TEST(Emitter, ALimitYieldsThePrefixOfTheFullSequence) {
    const Room room;
    const std::vector<ParticleSpec> all = emit_particles(spray(500), room);
    ASSERT_EQ(all.size(), 500u);
    for (std::size_t limit : {0u, 1u, 37u, 500u, 900u}) {
        const std::vector<ParticleSpec> some = emit_particles(spray(500), room, limit);
        ASSERT_EQ(some.size(), std::min<std::size_t>(limit, 500));
        for (std::size_t i = 0; i < some.size(); ++i) EXPECT_TRUE(same(some[i], all[i])) << "limit " << limit << ", particle " << i;
    }
}

TEST(Emitter, InitialParticlesAreTheListedOnesThenTheEmittedOnes) {
    Scene scene;
    scene.particles = {ParticleSpec{}, ParticleSpec{{0.5, 1.0, 0.0}, {1.0, 0.0, 0.0}, 0.1, 0.05}};
    scene.emitter = spray(100);
    const std::vector<ParticleSpec> initial = initial_particles(scene);
    const std::vector<ParticleSpec> emitted = emit_particles(*scene.emitter, scene.room);
    ASSERT_EQ(initial.size(), 102u);
    EXPECT_TRUE(same(initial[1], scene.particles[1]));
    for (std::size_t i = 0; i < emitted.size(); ++i) EXPECT_TRUE(same(initial[2 + i], emitted[i])) << i;
    // Built in one allocation: no second buffer of millions of particles at load.
    EXPECT_EQ(initial.capacity(), initial.size());
}

// The share of its starting space an emitter's balls fill, against closed forms: n balls of radius
// r at one point fill n (4/3 pi r^3) / (2r)^3 = n pi / 6 of a cube of side 2r; in a region of
// side L well inside the room, n (4/3 pi r^3) / (L + 2r)^3; a region reaching past the walls
// counts only the part inside (positions are clamped there); radii drawn from [r0, r1] count
// their mean cube, (r1^4 - r0^4) / (4 (r1 - r0)).
TEST(StartPacking, EmittedVolumeFractionClosedForms) {
    constexpr double pi = 3.141592653589793;
    Room room;
    room.center = {0, 5, 0};
    room.size = {10, 10, 10};
    Emitter e;
    e.count = 1000;
    e.radius_min = e.radius_max = 0.1;
    e.region_min = e.region_max = {0, 5, 0};
    EXPECT_NEAR(emitted_volume_fraction(e, room), 1000 * pi / 6, 1e-9);
    e.region_min = {-1, 4, -1};
    e.region_max = {1, 6, 1};
    const double ball = 4.0 / 3.0 * pi * 1e-3;
    EXPECT_NEAR(emitted_volume_fraction(e, room), 1000 * ball / (2.2 * 2.2 * 2.2), 1e-12);
    e.region_min = {-1, -4, -1};  // below the floor: centres from y = 0.1 up
    EXPECT_NEAR(emitted_volume_fraction(e, room), 1000 * ball / (2.2 * (6 - 0.1 + 0.2) * 2.2), 1e-12);
    e.radius_min = 0.05;
    e.radius_max = 0.15;
    const double mean_r3 = (std::pow(0.15, 4) - std::pow(0.05, 4)) / (4 * 0.1);
    e.region_min = {-1, 4, -1};
    // The same 2.2 m cube: the mean radius is 0.1 m again.
    EXPECT_NEAR(emitted_volume_fraction(e, room), 1000 * 4.0 / 3.0 * pi * mean_r3 / (2.2 * 2.2 * 2.2), 1e-12);
    e.count = 0;
    EXPECT_EQ(emitted_volume_fraction(e, room), 0.0);
}

}  // namespace
}  // namespace pl
