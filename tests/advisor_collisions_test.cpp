// The advisor's collisions row: the kinetic-theory estimate (collision_estimate.hpp) against its
// closed forms computed by hand for a two-ball scene, and the recommendation on both sides: a few
// small balls in a big room (off, and the runs measure exactly nothing), 500 balls of 2 cm over
// a quarter square metre of floor (on: they need three layers, and the runs measure it).
#include "physics/studies/advisor.hpp"
#include "physics/studies/advisor_runs.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace pl {
namespace {

constexpr double pi = std::numbers::pi;

std::string joined(const std::vector<std::string>& lines) {
    std::string s;
    for (const std::string& l : lines) s += l + "\n";
    return s;
}

const std::string& verdict_starting(const VariantAdvice& v, const std::string& start) {
    const auto it = std::find_if(v.verdicts.begin(), v.verdicts.end(), [&](const std::string& s) { return s.starts_with(start); });
    if (it == v.verdicts.end()) throw std::runtime_error("no verdict '" + start + "' in\n" + joined(v.verdicts));
    return *it;
}

const ModelRun& collisions_run(const VariantAdvice& v) {
    const auto it = std::find_if(v.runs.begin(), v.runs.end(), [](const ModelRun& r) { return r.term == "collisions"; });
    if (it == v.runs.end()) throw std::runtime_error("no collisions run");
    return *it;
}

// A 10 x 6 x 10 m room with its floor at y = 0.
Model big_room() {
    Model m;
    m.room.center = {0, 3, 0};
    m.room.size = {10, 6, 10};
    return m;
}

TEST(CollisionEstimate, TwoBallsMatchTheClosedForms) {
    // Radii 5 and 10 cm: one 1 m above the floor (its lowest point) thrown at 5 m/s, one lying on it.
    const std::vector<ParticleSpec> balls = {{{0, 1.05, 0}, {3, 0, 4}, 0.1, 0.05}, {{2, 0.1, 0}, {0, 0, 0}, 0.1, 0.1}};
    const double duration = 4.0;
    const CollisionEstimate e = estimate_collisions(big_room(), balls, duration);
    ASSERT_TRUE(e.applicable);
    const double volume = 600.0, n = 2.0 / volume;
    EXPECT_DOUBLE_EQ(e.room_volume_m3, volume);
    EXPECT_DOUBLE_EQ(e.number_density_m3, n);
    EXPECT_NEAR(e.volume_fraction, 4.0 / 3.0 * pi * (0.05 * 0.05 * 0.05 + 0.1 * 0.1 * 0.1) / volume, 1e-15);
    const double sigma = pi * 0.15 * 0.15;  // the pair's: pi (r_1 + r_2)^2
    EXPECT_NEAR(e.cross_section_m2, sigma, 1e-15);
    const double lambda = 1.0 / (std::sqrt(2.0) * n * sigma);  // 3001 m
    EXPECT_NEAR(e.mean_free_path_m, lambda, 1e-9 * lambda);
    const double v = std::sqrt((25.0 + 2.0 * 9.81 * 1.0 + 0.0) / 2.0);  // rms of the speeds at the floor
    EXPECT_NEAR(e.speed_m_s, v, 1e-12);
    EXPECT_NEAR(e.rate_per_s, v / lambda, 1e-15);
    EXPECT_NEAR(e.per_particle, duration * v / lambda, 1e-15);
    EXPECT_NEAR(e.total, e.per_particle, 1e-15);  // N nu T / 2 with N = 2
    EXPECT_DOUBLE_EQ(e.floor_area_m2, 100.0);
    EXPECT_NEAR(e.footprint_m2, pi * (0.05 * 0.05 + 0.1 * 0.1), 1e-15);
    EXPECT_NEAR(e.layers, e.footprint_m2 / (0.84 * 100.0), 1e-15);
    EXPECT_FALSE(e.must_stack);
    EXPECT_FALSE(e.matters);
}

TEST(CollisionEstimate, MixedRadiiAverageThePairCrossSections) {
    const std::vector<ParticleSpec> balls = {
        {{0, 1, 0}, {}, 1.0, 0.01}, {{1, 1, 0}, {}, 1.0, 0.03}, {{2, 1, 0}, {}, 1.0, 0.07}, {{3, 1, 0}, {}, 1.0, 0.2}};
    double sum = 0.0;
    int pairs = 0;
    for (std::size_t i = 0; i < balls.size(); ++i)
        for (std::size_t j = i + 1; j < balls.size(); ++j, ++pairs) sum += pi * std::pow(balls[i].radius + balls[j].radius, 2);
    EXPECT_NEAR(mean_pair_cross_section(balls), sum / pairs, 1e-15);
}

TEST(CollisionEstimate, NoGravityNoFloorAndOneParticleNothingToCollideWith) {
    Model weightless = big_room();
    weightless.world.gravity = Vec3(0.0);
    const std::vector<ParticleSpec> balls = {{{0, 1, 0}, {0, 0, 2}, 1.0, 0.1}, {{1, 1, 0}, {0, 0, 0}, 1.0, 0.1}};
    const CollisionEstimate e = estimate_collisions(weightless, balls, 1.0);
    EXPECT_DOUBLE_EQ(e.speed_m_s, std::sqrt(2.0));  // rms of 2 and 0 m/s
    EXPECT_EQ(e.floor_area_m2, 0.0);
    EXPECT_FALSE(e.must_stack);
    const CollisionEstimate one = estimate_collisions(big_room(), std::vector<ParticleSpec>(1), 1.0);
    EXPECT_FALSE(one.applicable);
    EXPECT_EQ(collision_reason(one), "one particle: nothing to collide with");
}

TEST(AdvisorCollisions, FewSmallBallsInABigRoomDoNotNeedThem) {
    Scene scene;
    scene.room = big_room().room;
    for (int k = 0; k < 5; ++k) scene.particles.push_back({{-4.0 + 2.0 * k, 1.0, 0}, {0, 0, 0}, 0.03, 0.01});
    const VariantAdvice v = advise(scene, {}).variants[0];
    const CollisionEstimate& e = v.collisions;
    EXPECT_EQ(e.particles, 5u);
    EXPECT_LT(e.total, 1e-3);
    EXPECT_GT(e.mean_free_path_m, 1e4);
    EXPECT_FALSE(e.matters);
    EXPECT_FALSE(v.collisions_recommended);
    // Two metres apart and dropped straight down: they never meet, and nothing moves at all.
    const ModelRun& run = collisions_run(v);
    EXPECT_FALSE(run.in_scene);
    EXPECT_FALSE(run.matters);
    for (AdviceMetric m : advice_metrics) EXPECT_EQ(run.metric(m).difference, 0.0) << to_string(m);
    const std::string& verdict = verdict_starting(v, "collisions do not matter: ");
    EXPECT_NE(verdict.find("expected collisions per particle over"), std::string::npos) << verdict;
    EXPECT_TRUE(verdict.ends_with("leave them off")) << verdict;

    scene.particles.resize(1);
    const VariantAdvice alone = advise(scene, {}).variants[0];
    EXPECT_EQ(collisions_run(alone).not_applicable, "one particle: nothing to collide with");
    verdict_starting(alone, "collisions: one particle: nothing to collide with");
}

TEST(AdvisorCollisions, TwoBallsThrownAtEachOtherMeetThoughTheEstimateSaysRarely) {
    // Head-on at 2 m/s each, 2 m apart at the same height: they meet after 0.5 s, in mid-air.
    // A gas of two balls in 600 m^3 would hardly ever collide (lambda = 6.8 km): the runs decide.
    Scene scene;
    scene.room = big_room().room;
    scene.particles = {{{-1, 3, 0}, {2, 0, 0}, 0.1, 0.05}, {{1, 3, 0}, {-2, 0, 0}, 0.1, 0.05}};
    const VariantAdvice v = advise(scene, {}).variants[0];
    EXPECT_FALSE(v.collisions.matters);
    EXPECT_LT(v.collisions.total, 0.1);
    EXPECT_TRUE(v.collisions_recommended);
    const ModelRun& run = collisions_run(v);
    EXPECT_TRUE(run.matters);
    // Closed form: the fall to the floor takes T = sqrt(2 x 2.95 m / g). Without collisions the
    // left ball lands at -1 + 2 T; with them the two touch when 2 - 4 t = 2 r, at x = -r, and it
    // leaves at -e x 2 m/s (equal masses, e = 0.9), landing at -r - 1.8 (T - t): 1.14 m apart.
    const double fall = std::sqrt(2.0 * 2.95 / 9.81), meet = (2.0 - 0.1) / 4.0;
    const double apart = (-1.0 + 2.0 * fall) - (-0.05 - 0.9 * 2.0 * (fall - meet));
    EXPECT_NEAR(run.metric(AdviceMetric::landing_point).difference, apart, 0.01);  // a few steps of 2 ms at 2 m/s
    const std::string& verdict = verdict_starting(v, "collisions matter: measured: ");
    EXPECT_NE(verdict.find(", although the estimate is "), std::string::npos) << verdict;
    EXPECT_TRUE(verdict.ends_with("turn them on")) << verdict;
}

// `count` balls of 2 cm dropped from rest over a quarter square metre of floor, 2 m high.
Scene pour_of(std::size_t count) {
    Scene scene;
    scene.room.center = {0, 1, 0};
    scene.room.size = {0.5, 2, 0.5};
    Emitter pour;
    pour.count = count;
    pour.region_min = {-0.2, 0.1, -0.2};
    pour.region_max = {0.2, 1.9, 0.2};
    pour.speed_min = pour.speed_max = 0.0;
    pour.radius_min = pour.radius_max = 0.02;
    scene.emitter = pour;
    return scene;
}

TEST(AdvisorCollisions, FiveHundredBallsOnAQuarterSquareMetreMustStack) {
    const Scene scene = pour_of(500);
    AdviceOptions o;
    o.max_duration_s = 3.0;  // the falls and the first bounces: enough to see the pile differ
    const Advice a = advise(scene, o);
    const VariantAdvice& v = a.variants[0];
    const CollisionEstimate& e = v.collisions;
    EXPECT_EQ(e.particles, 500u);
    EXPECT_EQ(e.measured_particles, 100u);
    EXPECT_NEAR(e.layers, 500 * pi * 0.02 * 0.02 / (0.84 * 0.25), 1e-12);  // 2.99
    EXPECT_TRUE(e.must_stack);
    EXPECT_TRUE(v.collisions_recommended);
    const std::string& verdict = verdict_starting(v, "collisions matter: 500 balls cannot lie in one layer on 0.25 m^2 of floor "
                                                     "(they need 3 layers); measured on the first 100 of 500 particles");
    EXPECT_TRUE(verdict.ends_with("turn them on")) << verdict;
    // Even the first 100 of them meet on the way down and on the floor: the runs differ.
    const ModelRun& run = collisions_run(v);
    EXPECT_TRUE(run.matters) << verdict;
    EXPECT_GT(run.metric(AdviceMetric::landing_point).difference, 1e-3) << verdict;
}

// A term's differences in a chaotic scene: the pour's balls meet in the air and on the floor, so
// moving every start by half a millimetre changes where they land by centimetres. Buoyancy (air
// over particles of 0.1% of their density) then changes them as much: the advice says they are
// within the scene's chaos and warns, and a scene whose balls never meet measures no chaos.
TEST(AdvisorCollisions, DifferencesNoLargerThanAMovedStartGivesAreMarkedAsTheScenesChaos) {
    Scene scene = pour_of(200);
    scene.collisions.enabled = true;
    AdviceOptions o;
    o.max_duration_s = 3.0;
    const VariantAdvice v = advise(scene, o).variants[0];
    ASSERT_TRUE(v.chaos_measured);
    ASSERT_TRUE(v.chaos.matters) << joined(v.warnings);
    // The nudged run is the variant's own scene: its settings, as the JSON reports them.
    EXPECT_EQ(v.chaos.model, v.configured);
    EXPECT_FALSE(v.chaos.with_wind);
    EXPECT_EQ(v.chaos.buoyancy, v.buoyancy);
    EXPECT_GT(v.chaos.metric(AdviceMetric::landing_point).difference, 1e-2) << "centimetres from half a millimetre";
    EXPECT_TRUE(v.warnings.front().starts_with("the trajectories are chaotic: moving every start by half the length tolerance "
                                               "(0.5 mm) changes "))
        << joined(v.warnings);
    // The rules, metric by metric: marked exactly when beyond tolerance and within twice the
    // nudge's; systematic when marked and the mean shift is past tolerance and 3 standard errors;
    // a row all within the chaos matters exactly when a metric is systematic. The collisions row,
    // the chaos's source, is not marked.
    std::size_t marked = 0;
    for (const ModelRun& r : v.runs) {
        if (r.term == "collisions") {
            EXPECT_FALSE(r.within_chaos);
            for (AdviceMetric m : advice_metrics) EXPECT_FALSE(r.metric(m).within_chaos) << to_string(m);
            continue;
        }
        bool all = r.not_applicable.empty(), beyond = false, shifted = false;
        for (AdviceMetric m : advice_metrics) {
            const MetricDelta& d = r.metric(m);
            const MetricDelta& c = v.chaos.metric(m);
            const bool within = d.beyond_tolerance && c.beyond_tolerance &&
                                std::abs(d.difference) <= chaos_factor * std::abs(c.difference);
            EXPECT_EQ(d.within_chaos, within) << r.term << ", " << to_string(m);
            const bool past = m != AdviceMetric::landing_point && d.samples >= systematic_samples &&
                              std::abs(d.mean) > AdviceTolerances{}.absolute(m) && std::abs(d.mean) > 3.0 * d.standard_error;
            EXPECT_EQ(d.systematic, within && past) << r.term << ", " << to_string(m);
            EXPECT_LE(std::abs(d.mean), std::abs(d.difference) + 1e-12) << r.term << ", " << to_string(m) << ": a mean past the largest";
            marked += d.within_chaos;
            if (d.beyond_tolerance) {
                all = all && within;
                beyond = true;
            }
            shifted = shifted || d.systematic;
        }
        EXPECT_EQ(r.within_chaos, all && beyond) << r.term;
        if (r.within_chaos) {
            EXPECT_EQ(r.matters, shifted) << r.term;
        }
    }
    EXPECT_GT(marked, 0u);
    const auto buoyancy = std::find_if(v.runs.begin(), v.runs.end(), [](const ModelRun& r) { return r.term == "buoyancy"; });
    ASSERT_NE(buoyancy, v.runs.end());
    if (buoyancy->within_chaos && !buoyancy->matters) {
        const std::string& verdict = verdict_starting(v, "buoyancy is off, and its effect cannot be told from the scene's chaos: ");
        EXPECT_NE(verdict.find("particle by particle all within the scene's chaos (moving every start by half the length tolerance "
                               "gives "),
                  std::string::npos)
            << verdict;
        EXPECT_NE(verdict.find("and no mean shift is beyond tolerance and 3 standard errors (largest: "), std::string::npos) << verdict;
    }

    // Five balls 2 m apart dropped straight down never meet: the moved starts change nothing
    // beyond tolerance (each lands half a millimetre from where it did), and nothing is marked.
    Scene apart;
    apart.room = big_room().room;
    apart.collisions.enabled = true;
    for (int k = 0; k < 5; ++k) apart.particles.push_back({{-4.0 + 2.0 * k, 1.0, 0}, {0, 0, 0}, 0.03, 0.01});
    const VariantAdvice calm = advise(apart, {}).variants[0];
    ASSERT_TRUE(calm.chaos_measured);
    EXPECT_FALSE(calm.chaos.matters);
    EXPECT_NEAR(calm.chaos.metric(AdviceMetric::landing_point).difference, 0.5e-3, 1e-12);
    for (const ModelRun& r : calm.runs) EXPECT_FALSE(r.within_chaos) << r.term;
    apart.collisions.enabled = false;
    EXPECT_FALSE(advise(apart, {}).variants[0].chaos_measured) << "no collisions: no chaos run";
}

TEST(AdvisorCollisions, ProgressCountsTheNudgedRun) {
    // The share done is reported before each run after the first, the nudged one included: it
    // rises evenly to the last run's start and then to 1 (it stood at 1 while the nudged run ran).
    Scene apart;
    apart.room = big_room().room;
    apart.collisions.enabled = true;
    for (int k = 0; k < 5; ++k) apart.particles.push_back({{-4.0 + 2.0 * k, 1.0, 0}, {0, 0, 0}, 0.03, 0.01});
    std::vector<double> shares;
    AdviceOptions o;
    o.progress = [&](double share) { shares.push_back(share); };
    const VariantAdvice v = advise(apart, o).variants[0];
    ASSERT_TRUE(v.chaos_measured);
    const std::size_t runs = v.distinct_runs;  // the nudged one among them
    ASSERT_EQ(shares.size(), runs) << ::testing::PrintToString(shares);  // before runs 2..runs, and the end
    for (std::size_t k = 0; k + 1 < shares.size(); ++k)
        EXPECT_DOUBLE_EQ(shares[k], static_cast<double>(k + 1) / static_cast<double>(runs)) << k;
    EXPECT_EQ(shares.back(), 1.0);
}

// The mean shift and its standard error over the particles: differences of 1, 2, 3 and 4 ms in
// landing time give a mean of 2.5 ms and a standard error of sd / sqrt(4) = 1.291 / 2 ms; a
// particle that lands in one run only is a bound, not a difference, and is left out.
TEST(AdvisorCollisions, MeanShiftsAndTheirStandardErrorsOverTheParticles) {
    RunOutcome value, baseline;
    value.end_time = baseline.end_time = 10.0;
    for (int k = 0; k < 4; ++k) {
        ParticleOutcome b;
        b.landing_time = 1.0 + k;
        ParticleOutcome v = b;
        v.landing_time = *b.landing_time + 1e-3 * (k + 1);
        baseline.particles.push_back(b);
        value.particles.push_back(v);
    }
    ParticleOutcome lands_once;
    lands_once.landing_time = 2.0;
    value.particles.push_back(lands_once);
    baseline.particles.push_back(ParticleOutcome{});
    ModelRun r;
    compare_runs(value, baseline, AdviceTolerances{}, r);
    const MetricDelta& d = r.metric(AdviceMetric::landing_time);
    EXPECT_EQ(d.samples, 4u);
    EXPECT_NEAR(d.mean, 2.5e-3, 1e-15);
    EXPECT_NEAR(d.standard_error, std::sqrt(5.0 / 3.0) * 1e-3 / 2.0, 1e-15);
    EXPECT_EQ(r.metric(AdviceMetric::landing_point).samples, 0u) << "a distance, never tallied";
}

}  // namespace
}  // namespace pl
