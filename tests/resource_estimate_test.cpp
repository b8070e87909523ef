// The memory estimate the CLI and the GUI both refuse by (physics/studies/resource_estimate.hpp).
#include "physics/studies/resource_estimate.hpp"

#include <gtest/gtest.h>

namespace pl {
namespace {

TEST(ResourceEstimate, CountsParticlesOfTheListAndTheEmitterAndEveryVariant) {
    Scene s;
    s.particles.resize(3);
    s.emitter = Emitter{};
    s.emitter->count = 2000000;
    s.variants.resize(7);
    const WorkEstimate w = work_of(s, 50.0);
    EXPECT_EQ(w.particles, 2000003u);
    EXPECT_EQ(w.variants, 7u);
    EXPECT_EQ(w.steps, 50.0);
    EXPECT_DOUBLE_EQ(estimated_bytes(w), 2000003.0 * (7.0 * double(bytes_per_particle_per_variant()) +
                                                      double(initial_bytes_per_particle())));
}

TEST(ResourceEstimate, CountsTheCollisionPassInTheVariantsWithCollisions) {
    // Collisions on in the scene; the second of three variants turns them off.
    Scene s;
    s.particles.resize(10);
    s.collisions.enabled = true;
    s.variants.resize(3);
    s.variants[1].collisions = CollisionSettings{};
    s.variants[1].collisions->enabled = false;
    const WorkEstimate w = work_of(s);
    EXPECT_EQ(w.variants, 3u);
    EXPECT_EQ(w.collision_variants, 2u);
    EXPECT_DOUBLE_EQ(estimated_bytes(w), 10.0 * (3.0 * double(bytes_per_particle_per_variant()) +
                                                 2.0 * double(collision_bytes_per_particle()) +
                                                 double(initial_bytes_per_particle())));
    // Colliding steps cost more: the two colliding variants take longer than three plain ones.
    const WorkEstimate plain{10, 3, 1e6, 0}, colliding{10, 3, 1e6, 2};
    EXPECT_GT(estimated_seconds(colliding), estimated_seconds(plain));
    s.collisions.enabled = false;
    EXPECT_EQ(work_of(s).collision_variants, 0u);
    // The pass holds far more than the particle state: what the refusal must not leave out.
    EXPECT_GT(collision_bytes_per_particle(), 10 * bytes_per_particle_per_variant());
}

TEST(ResourceEstimate, RefusesPastTheMemoryAvailableWithTheNumbers) {
    const std::uint64_t available = available_memory_bytes();
    if (available == 0) GTEST_SKIP() << "no MemAvailable in /proc/meminfo";
    EXPECT_EQ(memory_refusal({1000, 3, 0.0}), "");
    // Twice what is available, in particles of one variant.
    const std::uint64_t n = 2 * available / bytes_per_particle_per_variant() + 1;
    const std::string refused = memory_refusal({n, 1, 0.0});
    EXPECT_NE(refused.find("needs about"), std::string::npos) << refused;
    EXPECT_NE(refused.find(std::to_string(n) + " particles x 1 variant x " +
                           std::to_string(bytes_per_particle_per_variant()) + " bytes"),
              std::string::npos)
        << refused;
    EXPECT_NE(refused.find("available"), std::string::npos) << refused;
    // With collisions: the pass's share named, and the way out.
    const std::uint64_t m = 2 * available / (bytes_per_particle_per_variant() + collision_bytes_per_particle()) + 1;
    const std::string colliding = memory_refusal({m, 1, 0.0, 1});
    EXPECT_NE(colliding.find(std::to_string(collision_bytes_per_particle()) +
                             " bytes more per particle in the 1 variant with collisions"),
              std::string::npos)
        << colliding;
    EXPECT_NE(colliding.find("turn collisions off"), std::string::npos) << colliding;
    EXPECT_EQ(memory_refusal({m, 1, 0.0, 0}), "");  // the same particles fit without collisions
}

}  // namespace
}  // namespace pl
