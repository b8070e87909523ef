// The advisor's verdicts come from running the models: two contrasting scenes get opposite
// advice, and wind without drag is called out; vertical drops (no change in landing point or
// apex) are judged by landing time and impact speed, checked against the closed forms of a
// fall with quadratic drag and buoyancy.
#include "physics/studies/advisor.hpp"

#include "io/preset_io.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

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

const ModelRun& run_named(const VariantAdvice& v, const std::string& term) {
    const auto it = std::find_if(v.runs.begin(), v.runs.end(), [&](const ModelRun& r) { return r.term == term; });
    if (it == v.runs.end()) throw std::runtime_error("no run " + term);
    return *it;
}

TEST(Advisor, SlowDenseBallNeedsNoDragUnlessItBouncesLong) {
    // A 1 cm steel ball (33 g) tossed at 1.5 m/s from 0.5 m: drag is at most 3e-3 of its weight.
    // It moves neither the landing point nor the apex by 1 mm, nor the landing time by 1 ms...
    Scene scene = scene_with({{0, 0.5, 0}, {1.5, 0.5, 0}, 0.033, 0.01}, DragModel::quadratic);
    const VariantAdvice bouncing = advise(scene, {}).variants[0];
    const ModelRun& drag = run_named(bouncing, "drag");
    for (AdviceMetric m : {AdviceMetric::landing_point, AdviceMetric::apex_height, AdviceMetric::landing_time})
        EXPECT_FALSE(drag.metric(m).beyond_tolerance) << to_string(m) << "\n" << joined(bouncing.verdicts);
    // ...but over a dozen bounces (e = 0.8) it adds up: the time to rest moves by milliseconds.
    EXPECT_TRUE(drag.metric(AdviceMetric::time_to_rest).beyond_tolerance) << joined(bouncing.verdicts);
    EXPECT_GT(std::abs(drag.metric(AdviceMetric::time_to_rest).difference), 1e-3);
    EXPECT_TRUE(any_contains(bouncing.verdicts, "drag matters: ")) << joined(bouncing.verdicts);

    // The same toss into a floor that does not bounce it back (e = 0): only the impact speed,
    // 3.3 m/s, still moves by a few mm/s (drag/weight 0.3% at the end of the fall)...
    scene.contact.restitution = 0.0;
    const VariantAdvice still = advise(scene, {}).variants[0];
    const ModelRun& drag_still = run_named(still, "drag");
    for (AdviceMetric m : advice_metrics)
        EXPECT_EQ(drag_still.metric(m).beyond_tolerance, m == AdviceMetric::impact_speed) << to_string(m);
    EXPECT_GT(std::abs(drag_still.metric(AdviceMetric::impact_speed).difference), 1e-3);
    EXPECT_LT(std::abs(drag_still.metric(AdviceMetric::impact_speed).difference), 1e-2);
    // ...so at a 1 cm/s speed tolerance no drag is enough.
    AdviceOptions cm_per_s;
    cm_per_s.tolerance_mps = 0.01;
    const Advice a = advise(scene, cm_per_s);
    ASSERT_EQ(a.variants.size(), 1u);
    const VariantAdvice& v = a.variants[0];
    EXPECT_EQ(v.cheapest_adequate, DragModel::none) << joined(v.verdicts);
    EXPECT_TRUE(any_contains(v.verdicts, "drag changes nothing beyond tolerance")) << joined(v.verdicts);
    EXPECT_LT(v.max_drag_to_weight, 0.01);
    EXPECT_GT(v.re_max, 500.0);  // not Stokes flow, but it does not matter here
    EXPECT_TRUE(v.warnings.empty() || !any_contains(v.warnings, "Mach")) << joined(v.warnings);
    ASSERT_EQ(v.runs.size(), 10u);  // no drag, linear, quadratic, sphere_re, drag, buoyancy, added mass, ISA, collisions, wind
    EXPECT_LT(v.runs[0].landing_difference_m, 1e-3);
    EXPECT_EQ(v.runs[3].landing_difference_m, 0.0);  // the reference against itself
    EXPECT_FALSE(v.runs[3].matters);
}

TEST(Advisor, FastTennisBallNeedsQuadraticDragAndNotStokes) {
    // A tennis ball at 30 m/s: Re ~ 1e5, drag exceeds its weight.
    const Scene scene = scene_with({{-15, 0.5, 0}, {25, 15, 0}, 0.057, 0.033}, DragModel::linear);
    const Advice a = advise(scene, {});
    const VariantAdvice& v = a.variants[0];
    EXPECT_NE(v.cheapest_adequate, DragModel::none);
    EXPECT_NE(v.cheapest_adequate, DragModel::linear);
    EXPECT_TRUE(any_contains(v.verdicts, "linear drag is wrong here by")) << joined(v.verdicts);
    // The configured (Stokes) drag against none: tiny on a tennis ball, but beyond 1 mm.
    EXPECT_TRUE(any_contains(v.verdicts, "drag matters: ")) << joined(v.verdicts);
    EXPECT_GT(v.stokes_error_factor, 100.0);
    EXPECT_GT(v.max_drag_to_weight, 1.0);
    EXPECT_GT(v.re_max, 5e4);
    EXPECT_GT(v.runs[0].landing_difference_m, 1.0);  // no drag lands metres away
    // The scene's linear (Stokes) model is far outside its validity range: warned.
    EXPECT_TRUE(any_contains(v.warnings, "validity range")) << joined(v.warnings);
    // At a loose enough tolerance even the no-drag model is acceptable.
    AdviceOptions loose;
    loose.tolerance_m = 100.0;
    loose.tolerance_s = 100.0;
    loose.tolerance_mps = 100.0;
    EXPECT_EQ(advise(scene, loose).variants[0].cheapest_adequate, DragModel::none);
}

// Each distinct model the rows compare is run once: for one ball without drag, the scene itself,
// the reference (sphere_re), linear and quadratic drag, buoyancy and added mass turned on, ISA
// air and the constant air of the floor it is compared with. The drag toggle's "on" is the
// reference (the scene has no drag of its own), and its "off" the scene; collisions and wind do
// not apply to one ball in calm air. Before, the plan keyed runs by the builder that made them
// and ran the reference twice here (9 runs).
TEST(Advisor, EachDistinctModelRunsOnce) {
    const Scene scene = scene_with({{-15, 0.5, 0}, {25, 15, 0}, 0.057, 0.033}, DragModel::none);
    EXPECT_EQ(advise(scene, {}).variants[0].distinct_runs, 8u);
}

TEST(Advisor, WindWithoutDragHasNoEffectAndWindWithDragIsMeasured) {
    Scene scene = scene_with({{0, 0.5, 0}, {3, 4, 0}, 0.057, 0.033}, DragModel::none);
    scene.world.wind.kind = WindKind::constant;
    scene.world.wind.velocity = {5, 0, 0};
    scene.variants = {{"no drag", {}, {}, {}, {}, {}, {}}, {"quadratic", quadratic_drag(), {}, {}, {}, {}, {}}};
    const Advice a = advise(scene, {});
    ASSERT_EQ(a.variants.size(), 2u);
    EXPECT_TRUE(any_contains(a.variants[0].verdicts, "drag is off, so wind has no effect")) << joined(a.variants[0].verdicts);
    EXPECT_TRUE(any_contains(a.variants[1].verdicts, "wind matters: ")) << joined(a.variants[1].verdicts);
    ASSERT_EQ(a.variants[1].runs.size(), 10u);
    EXPECT_FALSE(a.variants[1].runs.back().with_wind);
    EXPECT_GT(a.variants[1].runs.back().landing_difference_m, 1e-3);
}

TEST(Advisor, WarnsAboveMachPointThree) {
    const Scene scene = scene_with({{-15, 0.5, 0}, {150, 5, 0}, 0.057, 0.033}, DragModel::quadratic);
    const Advice a = advise(scene, {});
    EXPECT_GT(a.variants[0].max_mach, 0.3);
    EXPECT_TRUE(any_contains(a.variants[0].warnings, "Mach")) << joined(a.variants[0].warnings);
}

// Vertical drops from rest: the landing point and the apex cannot tell drag or buoyancy apart,
// the landing time and impact speed can. Closed form of a fall from rest through height h with
// a = -g' + k v^2 (k = rho Cd A / 2m, g' = g (1 - rho_air / rho_particle) with buoyancy):
// terminal speed v_t = sqrt(g' / k), fall time t = (v_t / g') arccosh(exp(g' h / v_t^2)), impact
// speed v = v_t sqrt(1 - exp(-2 g' h / v_t^2)) (e.g. Taylor, Classical Mechanics, 2.4).
struct Fall {
    double time, speed;
};

Fall quadratic_fall(double h, double g, double k) {
    if (k == 0.0) return {std::sqrt(2.0 * h / g), std::sqrt(2.0 * g * h)};
    const double vt = std::sqrt(g / k);
    return {vt / g * std::acosh(std::exp(g * h / (vt * vt))), vt * std::sqrt(1.0 - std::exp(-2.0 * g * h / (vt * vt)))};
}

constexpr double g0 = 9.81;
constexpr double rho_air = 1.225;

double sphere_density(const ParticleSpec& p) { return p.mass / (4.0 / 3.0 * std::numbers::pi * std::pow(p.radius, 3)); }
double quadratic_k(const ParticleSpec& p) { return rho_air * 0.47 * std::numbers::pi * p.radius * p.radius / (2.0 * p.mass); }

// A 1 g foam ball of radius 5 cm (1.9 kg/m^3, rho_air / rho_particle = 0.641) dropped from 5.5 m.
const ParticleSpec foam_ball{{0, 5.5, 0}, {0, 0, 0}, 0.001, 0.05};
const double foam_drop = 5.5 - 0.05;  // to the floor at y = 0, centre a radius above it

TEST(Advisor, LightBallDropNeedsDragByLandingTimeThoughItLandsWhereItWould) {
    Scene scene = scene_with(foam_ball, DragModel::quadratic);
    const VariantAdvice v = advise(scene, {}).variants[0];
    const ModelRun& drag = run_named(v, "drag");  // quadratic (as configured) against none
    EXPECT_TRUE(drag.in_scene);
    EXPECT_TRUE(drag.matters);
    // Straight down either way: the first advisor's two metrics see nothing.
    EXPECT_LT(drag.metric(AdviceMetric::landing_point).difference, 1e-6);
    EXPECT_FALSE(drag.metric(AdviceMetric::apex_height).beyond_tolerance);
    const Fall air = quadratic_fall(foam_drop, g0, quadratic_k(foam_ball)), vacuum = quadratic_fall(foam_drop, g0, 0.0);
    const MetricDelta& t = drag.metric(AdviceMetric::landing_time);
    EXPECT_TRUE(t.beyond_tolerance);
    EXPECT_NEAR(t.value, air.time, 2e-3);  // event times: within a step (dt = 1 ms)
    EXPECT_NEAR(t.baseline, vacuum.time, 2e-3);
    EXPECT_GT(*t.relative(), 1.0);  // it takes more than twice as long
    const MetricDelta& speed = drag.metric(AdviceMetric::impact_speed);
    EXPECT_TRUE(speed.beyond_tolerance);
    EXPECT_EQ(speed.impact, 1);
    EXPECT_NEAR(speed.value, air.speed, 0.01 * air.speed);
    EXPECT_NEAR(speed.baseline, vacuum.speed, 0.01 * vacuum.speed);
    EXPECT_TRUE(any_contains(v.verdicts, "drag matters: landing time +1.7")) << joined(v.verdicts);
    EXPECT_NE(v.cheapest_adequate, DragModel::none);
}

TEST(Advisor, LightBallLandingTimesConvergeToTheClosedFormAtTheMethodsOrder) {
    // The measured landing times (with and without drag) against the closed form at dt and dt/2:
    // semi-implicit Euler is first order, so the error halves.
    const Fall air = quadratic_fall(foam_drop, g0, quadratic_k(foam_ball)), vacuum = quadratic_fall(foam_drop, g0, 0.0);
    auto errors = [&](double dt) {
        Scene scene = scene_with(foam_ball, DragModel::quadratic);
        scene.integrator.dt = dt;
        const MetricDelta t = run_named(advise(scene, {}).variants[0], "drag").metric(AdviceMetric::landing_time);
        return std::pair{std::abs(t.value - air.time), std::abs(t.baseline - vacuum.time)};
    };
    const auto [air_coarse, vacuum_coarse] = errors(2e-3);
    const auto [air_fine, vacuum_fine] = errors(1e-3);
    EXPECT_NEAR(std::log2(air_coarse / air_fine), 1.0, 0.1) << air_coarse << " " << air_fine;
    EXPECT_NEAR(std::log2(vacuum_coarse / vacuum_fine), 1.0, 0.1) << vacuum_coarse << " " << vacuum_fine;
    EXPECT_LT(air_fine, 1e-3);
}

TEST(Advisor, FeatherVsBallPresetNeedsDragBuoyancyAndAddedMassInAirAndNoneInVacuum) {
    const LoadResult r = load_preset(std::string(PL_SOURCE_DIR) + "/presets/feather_vs_ball.json");
    ASSERT_TRUE(r.ok()) << r.error_text();
    const Advice a = advise(*r.scene, {});
    ASSERT_EQ(a.variants.size(), 2u);
    EXPECT_NE(a.variants[0].cheapest_adequate, DragModel::none) << joined(a.variants[0].verdicts);
    EXPECT_TRUE(any_contains(a.variants[0].verdicts, "drag matters: landing time +")) << joined(a.variants[0].verdicts);
    for (const char* term : {"buoyancy matters: landing time +", "added mass matters: landing time +"})
        EXPECT_TRUE(any_contains(a.variants[0].verdicts, term)) << joined(a.variants[0].verdicts);
    // The vacuum variant (air of 1e-9 kg/m^3): drag would change nothing, and no ISA altitude
    // has so thin an air.
    EXPECT_TRUE(any_contains(a.variants[1].verdicts, "drag is off and would change nothing beyond tolerance"))
        << joined(a.variants[1].verdicts);
    EXPECT_TRUE(any_contains(a.variants[1].verdicts, "thinner than the ISA's anywhere")) << joined(a.variants[1].verdicts);
}

TEST(Advisor, BuoyancyOfALightBallMattersAndTheVerdictGivesTheDensityRatio) {
    const Scene scene = scene_with(foam_ball, DragModel::quadratic);  // buoyancy off
    const VariantAdvice v = advise(scene, {}).variants[0];
    const double ratio = rho_air / sphere_density(foam_ball);  // 0.64
    ASSERT_EQ(v.density_ratio.size(), 1u);
    EXPECT_NEAR(v.density_ratio[0], ratio, 1e-12 * ratio);
    const ModelRun& b = run_named(v, "buoyancy");
    EXPECT_FALSE(b.in_scene);
    EXPECT_TRUE(b.matters);
    // With buoyancy the net weight is (1 - ratio) of it: the same fall with g' = g (1 - ratio).
    const double k = quadratic_k(foam_ball);
    const Fall lifted = quadratic_fall(foam_drop, g0 * (1.0 - ratio), k), plain = quadratic_fall(foam_drop, g0, k);
    const MetricDelta& t = b.metric(AdviceMetric::landing_time);
    EXPECT_NEAR(t.difference, lifted.time - plain.time, 4e-3);
    EXPECT_GT(t.difference, 1.0);  // terminal speed down by sqrt(1 - 0.64): over a second later
    EXPECT_TRUE(any_contains(v.verdicts, "buoyancy is off but would change landing time +")) << joined(v.verdicts);
    EXPECT_TRUE(any_contains(v.verdicts, "rho_air/rho_particle = 0.641 (particle 0)")) << joined(v.verdicts);
    EXPECT_TRUE(any_contains(v.verdicts, ": turn it on")) << joined(v.verdicts);

    // The same ball with buoyancy on: the verdict is to keep it.
    Scene on = scene;
    on.world.buoyancy = true;
    const VariantAdvice w = advise(on, {}).variants[0];
    EXPECT_TRUE(run_named(w, "buoyancy").in_scene);
    EXPECT_TRUE(any_contains(w.verdicts, "buoyancy matters: landing time +")) << joined(w.verdicts);
}

TEST(Advisor, BuoyancyOfASteelBallInAShortDropDoesNotMatter) {
    // A 1 cm steel ball (7800 kg/m^3, 32.7 g) dropped 0.5 m without drag: buoyancy changes the
    // fall time by a factor 1/sqrt(1 - 1.6e-4), 25 us, far below the 1 ms tolerance.
    const ParticleSpec steel{{0, 0.51, 0}, {0, 0, 0}, 7800.0 * 4.0 / 3.0 * std::numbers::pi * 1e-6, 0.01};
    const VariantAdvice v = advise(scene_with(steel, DragModel::none), {}).variants[0];
    const double ratio = rho_air / 7800.0;
    EXPECT_NEAR(v.density_ratio[0], ratio, 1e-9 * ratio);
    const ModelRun& b = run_named(v, "buoyancy");
    EXPECT_FALSE(b.matters) << joined(v.verdicts);
    const double h = 0.5;
    const double expected = std::sqrt(2.0 * h / (g0 * (1.0 - ratio))) - std::sqrt(2.0 * h / g0);
    EXPECT_NEAR(b.metric(AdviceMetric::landing_time).difference, expected, 0.1 * expected);
    EXPECT_TRUE(any_contains(v.verdicts, "buoyancy is off and would change nothing beyond tolerance")) << joined(v.verdicts);
}

TEST(Advisor, AddedMassOfALightBallMattersByItsClosedForm) {
    // The foam ball in vacuum-like stillness (no drag) with buoyancy on: its fall accelerates at
    // g (m - rho V) / m, or g (m - rho V) / (m + rho V / 2) with the added mass: 0.36 g against
    // 0.27 g, so it lands later by sqrt(2 h / a_on) - sqrt(2 h / a_off).
    Scene scene = scene_with(foam_ball, DragModel::none);
    scene.world.buoyancy = true;
    const VariantAdvice v = advise(scene, {}).variants[0];
    const ModelRun& added = run_named(v, "added mass");
    EXPECT_FALSE(added.in_scene);
    EXPECT_TRUE(added.matters) << joined(v.verdicts);
    const double volume = 4.0 / 3.0 * std::numbers::pi * std::pow(foam_ball.radius, 3);
    const double m = foam_ball.mass;
    const double a_off = g0 * (m - rho_air * volume) / m, a_on = g0 * (m - rho_air * volume) / (m + 0.5 * rho_air * volume);
    const double expected = std::sqrt(2.0 * foam_drop / a_on) - std::sqrt(2.0 * foam_drop / a_off);
    EXPECT_NEAR(added.metric(AdviceMetric::landing_time).difference, expected, 2e-3);
    EXPECT_TRUE(any_contains(v.verdicts, "added mass is off but would change landing time +")) << joined(v.verdicts);
    EXPECT_TRUE(any_contains(v.verdicts, "added mass up to 0.321 of the particle's mass")) << joined(v.verdicts);
}

TEST(Advisor, ThinningAirMattersForAHighThrowNotForAShortDrop) {
    // A baseball hit 40 m high in a 100 m hall: the ISA's air is 0.4% thinner at the apex than at
    // the floor, so the ball flies farther than in constant floor-level air.
    Scene hall;
    hall.room.center = {0, 50, 0};
    hall.room.size = {300, 100, 40};
    hall.drag.model = DragModel::quadratic;
    hall.integrator.dt = 1e-3;
    hall.particles = {{{-140, 0.5, 0}, {30, 30, 0}, 0.145, 0.0366}};
    const VariantAdvice high = advise(hall, {}).variants[0];
    const ModelRun& isa = run_named(high, "ISA air (thinning with height)");
    EXPECT_FALSE(isa.in_scene);
    EXPECT_TRUE(isa.matters) << joined(high.verdicts);
    const double farther = isa.metric(AdviceMetric::range).difference;
    EXPECT_GT(farther, 0.01) << joined(high.verdicts);
    EXPECT_LT(farther, 2.0) << joined(high.verdicts);
    EXPECT_TRUE(any_contains(high.verdicts, "ISA density 1.225 kg/m^3 at the floor (0 m)")) << joined(high.verdicts);

    // A steel ball dropped half a metre sees 0.005% thinner air: nothing changes beyond tolerance.
    const ParticleSpec steel{{0, 0.51, 0}, {0, 0, 0}, 7800.0 * 4.0 / 3.0 * std::numbers::pi * 1e-6, 0.01};
    const VariantAdvice low = advise(scene_with(steel, DragModel::quadratic), {}).variants[0];
    EXPECT_FALSE(run_named(low, "ISA air (thinning with height)").matters) << joined(low.verdicts);
}

TEST(Advisor, EachMetricHasItsOwnTolerance) {
    // The light ball's drag effect is all in time and speed: loosen those and it no longer matters.
    AdviceOptions o;
    o.tolerance_s = 10.0;
    o.tolerance_mps = 20.0;
    const VariantAdvice v = advise(scene_with(foam_ball, DragModel::quadratic), o).variants[0];
    EXPECT_FALSE(run_named(v, "drag").matters) << joined(v.verdicts);
    // A relative tolerance of 200% of the vacuum values covers the +160% landing time too.
    AdviceOptions relative;
    relative.relative_tolerance = 2.0;
    EXPECT_FALSE(run_named(advise(scene_with(foam_ball, DragModel::quadratic), relative).variants[0], "drag")
                     .metric(AdviceMetric::landing_time)
                     .beyond_tolerance);
}

TEST(Advisor, CancelStopsTheVariantUnderWay) {
    Scene scene = scene_with(foam_ball, DragModel::quadratic);
    scene.variants = {{"quadratic", quadratic_drag(), {}, {}, {}, {}, {}}, {"again", quadratic_drag(), {}, {}, {}, {}, {}}};
    std::atomic<bool> cancel{false};
    AdviceOptions o;
    o.cancel = &cancel;
    o.progress = [&](double) { cancel = true; };  // after the first run of the first variant
    const Advice a = advise(scene, o);
    EXPECT_TRUE(a.cancelled);
    EXPECT_EQ(a.variants.size(), 1u);
}

}  // namespace
}  // namespace pl
