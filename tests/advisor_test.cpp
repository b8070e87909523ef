// The advisor's verdicts come from running the models: two contrasting scenes get opposite
// advice, and wind without drag is called out.
#include "physics/studies/advisor.hpp"

#include <gtest/gtest.h>

#include <algorithm>

namespace pl {
namespace {

bool any_contains(const std::vector<std::string>& lines, const std::string& text) {
    return std::any_of(lines.begin(), lines.end(), [&](const std::string& l) { return l.find(text) != std::string::npos; });
}

std::string joined(const std::vector<std::string>& lines) {
    std::string s;
    for (const std::string& l : lines) s += l + "\n";
    return s;
}

DragSettings quadratic_drag() {
    DragSettings d;
    d.model = DragModel::quadratic;
    return d;
}

Scene scene_with(ParticleSpec p, DragModel drag) {
    Scene s;
    s.room.center = {0, 5, 0};
    s.room.size = {40, 10, 40};
    s.drag.model = drag;
    s.integrator.dt = 1e-3;
    s.particles = {p};
    return s;
}

TEST(Advisor, SlowDenseBallNeedsNoDrag) {
    // A 1 cm steel ball (33 g) tossed at 1.5 m/s from 0.5 m: drag is ~1e-4 of its weight.
    const Scene scene = scene_with({{0, 0.5, 0}, {1.5, 0.5, 0}, 0.033, 0.01}, DragModel::quadratic);
    const Advice a = advise(scene, {});
    ASSERT_EQ(a.variants.size(), 1u);
    const VariantAdvice& v = a.variants[0];
    EXPECT_EQ(v.cheapest_adequate, DragModel::none) << joined(v.verdicts);
    EXPECT_TRUE(any_contains(v.verdicts, "model 'none' is enough at 1 mm tolerance")) << joined(v.verdicts);
    EXPECT_LT(v.max_drag_to_weight, 0.01);
    EXPECT_GT(v.re_max, 500.0);  // not Stokes flow, but it does not matter here
    EXPECT_TRUE(v.warnings.empty() || !any_contains(v.warnings, "Mach")) << joined(v.warnings);
    ASSERT_EQ(v.runs.size(), 4u);
    EXPECT_LT(v.runs[0].landing_difference_m, 1e-3);
    EXPECT_EQ(v.runs[3].landing_difference_m, 0.0);  // the reference against itself
}

TEST(Advisor, FastTennisBallNeedsQuadraticDragAndNotStokes) {
    // A tennis ball at 30 m/s: Re ~ 1e5, drag exceeds its weight.
    const Scene scene = scene_with({{-15, 0.5, 0}, {25, 15, 0}, 0.057, 0.033}, DragModel::linear);
    const Advice a = advise(scene, {});
    const VariantAdvice& v = a.variants[0];
    EXPECT_NE(v.cheapest_adequate, DragModel::none);
    EXPECT_NE(v.cheapest_adequate, DragModel::linear);
    EXPECT_TRUE(any_contains(v.verdicts, "linear drag is wrong here by")) << joined(v.verdicts);
    EXPECT_TRUE(any_contains(v.verdicts, "drag is needed at 1 mm tolerance")) << joined(v.verdicts);
    EXPECT_GT(v.stokes_error_factor, 100.0);
    EXPECT_GT(v.max_drag_to_weight, 1.0);
    EXPECT_GT(v.re_max, 5e4);
    EXPECT_GT(v.runs[0].landing_difference_m, 1.0);  // no drag lands metres away
    // The scene's linear (Stokes) model is far outside its validity range: warned.
    EXPECT_TRUE(any_contains(v.warnings, "validity range")) << joined(v.warnings);
    // At a loose enough tolerance even the no-drag model is acceptable.
    AdviceOptions loose;
    loose.tolerance_m = 100.0;
    EXPECT_EQ(advise(scene, loose).variants[0].cheapest_adequate, DragModel::none);
}

TEST(Advisor, WindWithoutDragHasNoEffectAndWindWithDragIsMeasured) {
    Scene scene = scene_with({{0, 0.5, 0}, {3, 4, 0}, 0.057, 0.033}, DragModel::none);
    scene.world.wind.kind = WindKind::constant;
    scene.world.wind.velocity = {5, 0, 0};
    scene.variants = {{"no drag", {}, {}, {}, {}, {}, {}}, {"quadratic", quadratic_drag(), {}, {}, {}, {}, {}}};
    const Advice a = advise(scene, {});
    ASSERT_EQ(a.variants.size(), 2u);
    EXPECT_TRUE(any_contains(a.variants[0].verdicts, "drag is off, so wind has no effect")) << joined(a.variants[0].verdicts);
    EXPECT_TRUE(any_contains(a.variants[1].verdicts, "wind (constant) moves")) << joined(a.variants[1].verdicts);
    ASSERT_EQ(a.variants[1].runs.size(), 5u);
    EXPECT_FALSE(a.variants[1].runs.back().with_wind);
    EXPECT_GT(a.variants[1].runs.back().landing_difference_m, 1e-3);
}

TEST(Advisor, WarnsAboveMachPointThree) {
    const Scene scene = scene_with({{-15, 0.5, 0}, {150, 5, 0}, 0.057, 0.033}, DragModel::quadratic);
    const Advice a = advise(scene, {});
    EXPECT_GT(a.variants[0].max_mach, 0.3);
    EXPECT_TRUE(any_contains(a.variants[0].warnings, "Mach")) << joined(a.variants[0].warnings);
}

}  // namespace
}  // namespace pl
