// The count of overlapping spheres (physics/model/sphere_overlaps.hpp) against the all-pairs
// loop, with radii over many scales, and its stop at the limit; and the listed balls' start rule
// (physics/model/start_packing.hpp) on a crowd that a box around all of them would not catch.
#include "physics/model/sphere_overlaps.hpp"
#include "physics/model/start_packing.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace pl {
namespace {

// The reference: every pair, the same test.
OverlapCount all_pairs(const std::vector<Sphere>& s, double tolerance) {
    OverlapCount c;
    for (std::uint32_t i = 0; i < s.size(); ++i)
        for (std::uint32_t j = i + 1; j < s.size(); ++j) {
            const double contact = s[i].radius + s[j].radius;
            const double distance = glm::distance(s[i].centre, s[j].centre);
            if (!(distance < contact * (1.0 - tolerance))) continue;
            ++c.pairs;
            if ((contact - distance) / contact > c.deepest_share) {
                c.deepest_share = (contact - distance) / contact;
                c.deepest_a = i;
                c.deepest_b = j;
            }
        }
    return c;
}

// n spheres in a cube of side `side`, radii log-uniform from r_min to r_max.
std::vector<Sphere> scattered(std::size_t n, double side, double r_min, double r_max, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> at(0.0, side), log_r(std::log(r_min), std::log(r_max));
    std::vector<Sphere> s(n);
    for (Sphere& b : s) b = {Vec3(at(rng), at(rng), at(rng)), std::exp(log_r(rng))};
    return s;
}

// The same pairs, and the same deepest one, as the reference; `least` of them at least (the scene
// tests something).
void expect_same_count(const std::vector<Sphere>& s, double tolerance, std::size_t least) {
    const OverlapCount want = all_pairs(s, tolerance);
    EXPECT_GE(want.pairs, least);
    const OverlapCount got = count_overlaps(s, s.size() * s.size(), tolerance);
    EXPECT_EQ(got.pairs, want.pairs);
    EXPECT_FALSE(got.over_limit);
    EXPECT_FALSE(got.undecided);
    EXPECT_EQ(got.deepest_share, want.deepest_share);
    if (want.pairs > 0) {
        EXPECT_EQ(got.deepest_a, want.deepest_a);
        EXPECT_EQ(got.deepest_b, want.deepest_b);
    }
}

TEST(SphereOverlaps, MatchesEveryPairWithLikeRadii) {
    for (const double side : {0.5, 1.0, 3.0}) expect_same_count(scattered(1500, side, 0.02, 0.02, 3), 0.0, 10);
}

TEST(SphereOverlaps, MatchesEveryPairWithRadiiOverManyScales) {
    // 1 um to 0.3 m: a dozen levels of cells, pairs met across all of them.
    expect_same_count(scattered(2000, 1.0, 1e-6, 0.3, 5), 0.0, 10000);
    expect_same_count(scattered(2000, 1.0, 1e-3, 0.05, 7), 1e-4, 400);
    // A few large balls among many small ones.
    std::vector<Sphere> s = scattered(2000, 2.0, 0.01, 0.01, 11);
    for (const Sphere& big : scattered(5, 2.0, 0.4, 0.6, 13)) s.push_back(big);
    expect_same_count(s, 0.0, 500);
}

TEST(SphereOverlaps, MatchesEveryPairAtTheExtremesOfScale) {
    // Radii from 1e-300 m to 1 m, and every centre at one point (no span).
    std::vector<Sphere> s = scattered(300, 1.0, 1e-300, 1.0, 17);
    expect_same_count(s, 0.0, 20);
    for (Sphere& b : s) b.centre = Vec3(0.25);
    expect_same_count(s, 0.0, 300 * 299 / 2);
}

TEST(SphereOverlaps, TouchingBallsAreNotCountedWithinTheTolerance) {
    // A cubic lattice of touching balls (spacing one diameter): 0 pairs with a tolerance; pressed
    // 1% closer, each ball overlaps its 6 neighbours: 3 (n - n^(2/3)) pairs for n = k^3 balls.
    const double r = 0.05;
    const int k = 8;
    for (const double spacing : {2.0 * r, 0.99 * 2.0 * r}) {
        std::vector<Sphere> s;
        for (int x = 0; x < k; ++x)
            for (int y = 0; y < k; ++y)
                for (int z = 0; z < k; ++z) s.push_back({spacing * Vec3(x, y, z), r});
        const OverlapCount c = count_overlaps(s, 100000, 1e-4);
        EXPECT_EQ(c.pairs, spacing == 2.0 * r ? 0u : 3u * (k * k * k - k * k)) << spacing;
        if (spacing < 2.0 * r) {
            EXPECT_NEAR(c.deepest_share, 0.01, 1e-12);
        }
    }
}

TEST(SphereOverlaps, StopsJustPastTheLimit) {
    // 1e4 balls at one point are 5e7 pairs: the count stops at limit + 1.
    const std::vector<Sphere> clump(10000, Sphere{Vec3(1.0), 0.01});
    const OverlapCount c = count_overlaps(clump, 80000, 1e-4);
    EXPECT_TRUE(c.over_limit);
    EXPECT_FALSE(c.undecided);
    EXPECT_EQ(c.pairs, 80001u);
    EXPECT_EQ(c.deepest_share, 1.0);  // concentric
    EXPECT_EQ(count_overlaps(clump, 100, 0.0).pairs, 101u);
    EXPECT_EQ(count_overlaps({}, 0, 0.0).pairs, 0u);
    EXPECT_EQ(count_overlaps(std::vector<Sphere>(1, Sphere{Vec3(0.0), 1.0}), 0, 0.0).pairs, 0u);
}

ParticleSpec ball_at(const Vec3& x, double r) {
    ParticleSpec p;
    p.position = x;
    p.radius = r;
    return p;
}

TEST(StartPacking, ACrowdBesideFarBallsIsCaughtByItsOverlaps) {
    // 50 balls at one point beside 8 in the corners of a 10 m room: the box their centres span
    // is the room, where they fill a share of 1e-3, but they overlap in 1225 pairs, more than 8
    // per ball (464).
    std::vector<ParticleSpec> listed(50, ball_at(Vec3(0.0, 1.0, 0.0), 0.033));
    for (const double x : {-4.9, 4.9})
        for (const double y : {-2.9, 2.9})
            for (const double z : {-4.9, 4.9}) listed.push_back(ball_at({x, y, z}, 0.033));
    const OverlapCount crowd = listed_overlaps(listed);
    EXPECT_TRUE(crowd.over_limit);
    EXPECT_EQ(crowd.pairs, 465u);
    // Spread over a row, touching, they do not overlap at all.
    for (std::size_t i = 0; i < 50; ++i) listed[i].position.x = 0.066 * static_cast<double>(i) - 1.6;
    const OverlapCount row = listed_overlaps(listed);
    EXPECT_FALSE(row.over_limit);
    EXPECT_EQ(row.pairs, 0u);
}

}  // namespace
}  // namespace pl
