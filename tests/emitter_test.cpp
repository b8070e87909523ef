// The emitter is one seeded draw sequence: any prefix of it is the same particles, which lets the
// GUI take particle 0 of a two-million-particle scene without building the other 1,999,999.
#include "physics/model/emitter.hpp"
#include "physics/model/scene.hpp"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace pl
