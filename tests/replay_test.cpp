// Replay: a scene's trajectory depends only on the scene and the number of steps, never on
// the frame rate; all variants share the same simulated time.
#include "physics/stepping/experiment.hpp"

#include <gtest/gtest.h>

#include <cstring>

namespace pl {
namespace {

Scene two_variant_scene() {
    Scene s;
    s.room = {{0, 3, 0}, {10, 6, 10}};
    s.drag.model = DragModel::quadratic;
    s.integrator.dt = 0.002;
    s.particles = {{{0, 2, 0}, {3, 4, 1}, 0.057, 0.033}, {{-2, 1, 2}, {5, 6, -2}, 0.057, 0.033}};
    Variant coarse;
    coarse.label = "rk4 coarse";
    coarse.integrator = IntegratorSettings{Method::rk4, 0.01};
    Variant windy;
    windy.label = "gusty";
    windy.wind = WindSettings{};
    windy.wind->kind = WindKind::gust;
    windy.wind->velocity = {2, 0, 0};
    Variant base;
    base.label = "base";
    s.variants = {base, coarse, windy};
    return s;
}

bool identical(const ParticleState& a, const ParticleState& b) {
    auto same = [](const StateArray<double>& x, const StateArray<double>& y) {
        return x.size() == y.size() && std::memcmp(x.data(), y.data(), x.size() * sizeof(double)) == 0;
    };
    return same(a.x, b.x) && same(a.y, b.y) && same(a.z, b.z) && same(a.vx, b.vx) && same(a.vy, b.vy) &&
           same(a.vz, b.vz) && same(a.dissipated_drag, b.dissipated_drag) && a.resting == b.resting;
}

TEST(Replay, DifferentFrameTimesSameStepsSameStateBitForBit) {
    Experiment smooth(two_variant_scene()), jerky(two_variant_scene());
    for (int f = 0; f < 300; ++f) smooth.advance_real(1.0 / 60.0);
    const double frame_times[] = {0.001, 0.05, 0.0331, 0.0002, 0.1, 0.017};
    for (int f = 0; jerky.base_steps() < smooth.base_steps(); ++f) {
        const double dt = frame_times[f % 6];
        const double left = static_cast<double>(smooth.base_steps() - jerky.base_steps()) * jerky.base_dt();
        jerky.advance_real(std::min(dt, left));
    }
    ASSERT_EQ(jerky.base_steps(), smooth.base_steps());
    for (std::size_t v = 0; v < smooth.variant_count(); ++v) {
        EXPECT_EQ(smooth.run(v).step_count(), jerky.run(v).step_count());
        EXPECT_TRUE(identical(smooth.run(v).state(), jerky.run(v).state())) << "variant " << v;
    }
}

TEST(Replay, SameSceneTwiceIsBitIdentical) {
    Experiment a(two_variant_scene()), b(two_variant_scene());
    a.run_until(3.0);
    b.run_until(3.0);
    for (std::size_t v = 0; v < a.variant_count(); ++v) EXPECT_TRUE(identical(a.run(v).state(), b.run(v).state()));
}

TEST(Replay, VariantsAdvanceInLockstep) {
    Experiment e(two_variant_scene());
    for (int f = 0; f < 200; ++f) {
        e.advance_real(0.013);
        for (const Simulation& s : e.runs()) {
            // Each variant is at the latest point of its own step grid not after the common time.
            EXPECT_LE(s.time(), e.time() + 1e-12);
            EXPECT_GT(s.time() + s.dt(), e.time() + 1e-12);
        }
    }
}

TEST(Replay, VariantsAreIndependent) {
    Scene s = two_variant_scene();
    Experiment before(s);
    before.run_until(2.0);
    s.variants[2].wind->velocity = {-5, 0, 3};  // edit one variant only
    Experiment after(s);
    after.run_until(2.0);
    EXPECT_TRUE(identical(before.run(0).state(), after.run(0).state()));
    EXPECT_TRUE(identical(before.run(1).state(), after.run(1).state()));
    EXPECT_FALSE(identical(before.run(2).state(), after.run(2).state()));
}

TEST(Replay, ClockCapsStepsPerFrameAndReportsFallingBehind) {
    FixedStepClock clock;
    clock.max_steps_per_frame = 100;
    FixedStepClock::Tick t = clock.advance(1.0, 0.002);  // 500 steps owed
    EXPECT_EQ(t.steps, 100u);
    EXPECT_TRUE(t.behind);
    t = clock.advance(0.01, 0.002);
    EXPECT_EQ(t.steps, 5u);
    EXPECT_FALSE(t.behind);
}

}  // namespace
}  // namespace pl
