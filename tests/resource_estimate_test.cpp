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
}

}  // namespace
}  // namespace pl
