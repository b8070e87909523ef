// The pair cache (physics/collide/pair_cache.hpp) gives, at every call, exactly the pairs of the
// all-pairs loop, while it runs the grid only now and then: particles that move, bounce, jump,
// fall asleep, wake and leave.
#include "physics/collide/pair_cache.hpp"

#include <gtest/gtest.h>

#include <random>

namespace pl::collide {
namespace {

// Spheres moving in straight lines in a cube of side `side`, reflected at its faces.
struct Movers {
    std::vector<double> x, v, r;  // 3 per particle for x and v
    SweptBoxes boxes;

    Movers(std::size_t n, double side, double speed, std::uint32_t seed) : x(3 * n), v(3 * n), r(n) {
        std::mt19937 rng(seed);
        std::uniform_real_distribution<double> pos(-0.5 * side, 0.5 * side), vel(-speed, speed), rad(0.004, 0.01);
        for (std::size_t i = 0; i < n; ++i) {
            r[i] = rad(rng);
            for (int k = 0; k < 3; ++k) {
                x[3 * i + k] = pos(rng);
                v[3 * i + k] = vel(rng);
            }
        }
        boxes.resize(n);
        for (std::uint32_t i = 0; i < n; ++i) boxes.ids.push_back(i);
        step(0.0, side);
    }
    // One step of dt: the swept boxes from the old to the new positions, and their reach.
    void step(double dt, double side) {
        boxes.reach = 0.0;
        std::fill(boxes.move.begin(), boxes.move.end(), 0.0f);
        for (std::size_t i = 0; i < r.size(); ++i)
            for (int k = 0; k < 3; ++k) {
                const double x0 = x[3 * i + k];
                double x1 = x0 + dt * v[3 * i + k];
                if (std::abs(x1) > 0.5 * side) {
                    v[3 * i + k] = -v[3 * i + k];
                    x1 = x0;
                }
                x[3 * i + k] = x1;
                boxes.box[i].lo[k] = std::min(x0, x1) - r[i];
                boxes.box[i].hi[k] = std::max(x0, x1) + r[i];
                boxes.move[i] = std::max(boxes.move[i], static_cast<float>(std::abs(x1 - x0)));
                boxes.reach = std::max(boxes.reach, std::abs(x1 - x0));
            }
    }
};

std::vector<Pair> expected_pairs(const SweptBoxes& boxes, const std::vector<std::uint8_t>& asleep) {
    std::vector<Pair> all, kept;
    all_pairs(boxes, all);
    for (const Pair& p : all)
        if (asleep.empty() || !(asleep[p.a] && asleep[p.b])) kept.push_back(p);
    return kept;
}

TEST(PairCache, MovingGasSameAsAllPairsWhileTheGridRunsRarely) {
    // A dilute gas over 40 steps, some particles turned around at random (as collisions do):
    // every call gives the all-pairs loop's pairs, on one and two threads, and the grid runs
    // about once in steps_ahead steps.
    constexpr double side = 1.0, dt = 1e-3;
    Movers gas(3000, side, 2.0, 3);
    std::mt19937 rng(4);
    PairCache one, two;
    std::vector<Pair> serial, threaded;
    std::size_t pairs_seen = 0;
    for (int call = 0; call < 40; ++call) {
        gas.step(dt, side);
        for (int turn = 0; turn < 20; ++turn) {  // turned, and some sped up: they leave
            const std::size_t i = rng() % gas.r.size();
            const double factor = turn % 2 == 0 ? -1.0 : -3.0;
            for (int k = 0; k < 3; ++k) gas.v[3 * i + k] *= factor;
        }
        one.find_pairs(gas.boxes, serial, nullptr, 1);
        two.find_pairs(gas.boxes, threaded, nullptr, 2);
        const std::vector<Pair> expected = expected_pairs(gas.boxes, {});
        ASSERT_EQ(serial, expected) << "call " << call;
        ASSERT_EQ(threaded, expected) << "call " << call;
        pairs_seen += expected.size();
    }
    EXPECT_GT(pairs_seen, 1000u);
    EXPECT_GT(one.margin(), 0.0);
    EXPECT_EQ(one.calls(), 40u);
    EXPECT_LE(one.grid_runs(), 14u) << "the fat boxes should last a few steps";
    EXPECT_EQ(one.grid_runs(), two.grid_runs());
}

TEST(PairCache, ThreadedPassesOnACrowdSameAsTheGrid) {
    // Enough particles and fat pairs for every pass to split over threads; the reference is the
    // grid run afresh each call (itself checked against all pairs in broad_phase_test.cpp).
    constexpr double side = 1.0, dt = 1e-3;
    Movers crowd(20000, side, 2.0, 5);
    PairCache one, two;
    std::vector<Pair> serial, threaded, fresh;
    for (int call = 0; call < 12; ++call) {
        crowd.step(dt, side);
        BroadPhase grid;
        grid.find_pairs(crowd.boxes, fresh);
        one.find_pairs(crowd.boxes, serial, nullptr, 1);
        two.find_pairs(crowd.boxes, threaded, nullptr, 2);
        ASSERT_EQ(serial, fresh) << "call " << call;
        ASSERT_EQ(threaded, fresh) << "call " << call;
        EXPECT_GT(fresh.size(), 2000u);
    }
    EXPECT_GT(two.fat_pair_count(), 16384u) << "too few to test the pairs in slices";
    EXPECT_LT(two.grid_runs(), 12u);
}

TEST(PairCache, AJumpALeaverAndAWakerAreSeenAtOnce) {
    // Within the fat boxes' lifetime: a particle jumps onto another (a user's drag), one leaves
    // (frozen), and one that slept beside a sleeper wakes. Each is in (or out of) the very
    // next call's pairs.
    constexpr double side = 1.0, dt = 1e-3;
    Movers gas(4000, side, 0.5, 6);
    std::vector<std::uint8_t> asleep(gas.r.size(), 0);
    asleep[10] = asleep[11] = 1;
    for (int k = 0; k < 3; ++k) {  // 10 and 11 overlap, both asleep, still
        gas.x[3 * 11 + k] = gas.x[3 * 10 + k] + 0.001;
        gas.v[3 * 10 + k] = gas.v[3 * 11 + k] = 0.0;
    }
    PairCache cache;
    std::vector<Pair> pairs;
    auto check = [&](const char* what) {
        cache.find_pairs(gas.boxes, pairs, asleep.data(), 1);
        ASSERT_EQ(pairs, expected_pairs(gas.boxes, asleep)) << what;
    };
    gas.step(dt, side);
    check("start");
    const Pair sleepers{10, 11};
    EXPECT_EQ(std::count(pairs.begin(), pairs.end(), sleepers), 0);
    gas.step(dt, side);
    check("reused");
    const std::uint64_t runs = cache.grid_runs();

    for (int k = 0; k < 3; ++k) gas.x[3 * 500 + k] = gas.x[3 * 900 + k];  // a jump: mended
    gas.step(dt, side);
    check("jump");
    EXPECT_EQ(cache.grid_runs(), runs);
    EXPECT_EQ(cache.mends(), 1u);
    EXPECT_EQ(std::count(pairs.begin(), pairs.end(), Pair{500, 900}), 1);

    gas.boxes.ids.erase(std::find(gas.boxes.ids.begin(), gas.boxes.ids.end(), 900u));  // a leaver
    gas.step(dt, side);
    check("leaver");
    EXPECT_EQ(std::count(pairs.begin(), pairs.end(), Pair{500, 900}), 0);

    gas.step(dt, side);
    check("reused again");
    asleep[11] = 0;  // wakes where it slept: inside its fat box
    gas.step(dt, side);
    check("waker");
    EXPECT_EQ(std::count(pairs.begin(), pairs.end(), sleepers), 1);
}

TEST(PairCache, MendedBoxesMeetTheGridsTheMendedAndEachOther) {
    // Within the fat boxes' lifetime, short jumps (a few centimetres: a mend queries few cells):
    // two neighbours jump together in one call (two leavers); in the next, a third jumps onto one
    // of them (a leaver against a box mended before, which the grid holds stale) and a fifth onto
    // a fourth, still one (through the grid). Every call gives the all-pairs loop's pairs; the
    // grid does not run.
    constexpr double side = 1.0, dt = 1e-3;
    Movers gas(3000, side, 0.5, 11);
    PairCache cache;
    std::vector<Pair> pairs;
    auto check = [&](const char* what) {
        cache.find_pairs(gas.boxes, pairs);
        ASSERT_EQ(pairs, expected_pairs(gas.boxes, {})) << what;
    };
    auto distance = [&](std::size_t i, std::size_t j) {
        double d2 = 0.0;
        for (int k = 0; k < 3; ++k) d2 += (gas.x[3 * i + k] - gas.x[3 * j + k]) * (gas.x[3 * i + k] - gas.x[3 * j + k]);
        return std::sqrt(d2);
    };
    auto nearest = [&](std::size_t i, std::initializer_list<std::size_t> not_these) {
        std::size_t best = i;
        for (std::size_t j = 0; j < gas.r.size(); ++j)
            if (j != i && std::find(not_these.begin(), not_these.end(), j) == not_these.end() &&
                (best == i || distance(i, j) < distance(i, best)))
                best = j;
        return best;
    };
    auto jump = [&](std::size_t i, std::size_t next_to) {
        for (int k = 0; k < 3; ++k) gas.x[3 * i + k] = gas.x[3 * next_to + k] + (k == 0 ? 0.5 : 0.0) * (gas.r[i] + gas.r[next_to]);
    };
    gas.step(dt, side);
    check("start");
    const std::uint64_t runs = cache.grid_runs();
    const std::size_t a = 100, b = nearest(a, {}), c = nearest(a, {b}), d = 2000, e = nearest(d, {a, b, c});
    ASSERT_LT(distance(a, b), 0.1);
    for (int k = 0; k < 3; ++k) gas.x[3 * a + k] = 0.5 * (gas.x[3 * a + k] + gas.x[3 * b + k]);
    jump(b, a);
    gas.step(dt, side);
    check("two leavers");
    EXPECT_EQ(std::count(pairs.begin(), pairs.end(), Pair{std::uint32_t(std::min(a, b)), std::uint32_t(std::max(a, b))}), 1);
    jump(c, a);
    jump(e, d);
    gas.step(dt, side);
    check("leavers by a mended one and by a still one");
    EXPECT_EQ(std::count(pairs.begin(), pairs.end(), Pair{std::uint32_t(std::min(a, c)), std::uint32_t(std::max(a, c))}), 1);
    EXPECT_EQ(std::count(pairs.begin(), pairs.end(), Pair{std::uint32_t(std::min(d, e)), std::uint32_t(std::max(d, e))}), 1);
    EXPECT_EQ(cache.grid_runs(), runs);
    EXPECT_EQ(cache.mends(), 2u);
}

TEST(PairCache, ACrowdUnderAFarFastBallKeepsItsFatBoxesSmall) {
    // 3000 balls crowded in a 0.3 m cube and one ball 100 m away moving 10 m a step: the mean
    // spacing of the region is metres, the farthest move 10 m; each ball's margin comes from its
    // own move (at most 0.5 mm), so the crowd's fat pairs stay a few per ball (not millions), and
    // then none: a crowd gets no margin.
    Movers crowd(3001, 0.3, 0.5, 9);
    crowd.step(1e-3, 0.3);
    for (int k = 0; k < 3; ++k) {
        crowd.boxes.box[3000].lo[k] = 100.0;
        crowd.boxes.box[3000].hi[k] = 110.0;
    }
    crowd.boxes.reach = crowd.boxes.move[3000] = 10.0f;
    PairCache cache;
    std::vector<Pair> pairs;
    cache.find_pairs(crowd.boxes, pairs);
    EXPECT_EQ(pairs, expected_pairs(crowd.boxes, {}));
    EXPECT_GT(cache.margin(), 0.0);
    EXPECT_LT(cache.fat_pair_count(), 20 * crowd.r.size());
    EXPECT_GT(pairs.size(), 1000u);
    // More than one fat pair per ball: a crowd, where testing them each step costs what the grid
    // does. A call on the same boxes reuses them; then the far ball moves on (out of its fat
    // box, into more cells than a mend may query): the grid runs again, without a margin.
    EXPECT_GT(cache.fat_pair_count(), crowd.r.size());
    cache.find_pairs(crowd.boxes, pairs);
    EXPECT_EQ(cache.grid_runs(), 1u);
    for (int k = 0; k < 3; ++k) {
        crowd.boxes.box[3000].lo[k] = 110.0;
        crowd.boxes.box[3000].hi[k] = 120.0;
    }
    cache.find_pairs(crowd.boxes, pairs);
    EXPECT_EQ(pairs, expected_pairs(crowd.boxes, {}));
    EXPECT_EQ(cache.grid_runs(), 2u);
    EXPECT_EQ(cache.margin(), 0.0);
}

TEST(PairCache, NoReachMeansNoMarginAndOnlyStillBoxesAreReused) {
    // Without a reach the fat boxes are the boxes: a call on the same boxes reuses the pairs, a
    // call on moved ones runs the grid.
    Movers gas(3000, 0.6, 0.5, 7);
    gas.boxes.reach = 0.0;
    PairCache cache;
    std::vector<Pair> pairs;
    cache.find_pairs(gas.boxes, pairs);
    EXPECT_EQ(pairs, expected_pairs(gas.boxes, {}));
    EXPECT_EQ(cache.margin(), 0.0);
    cache.find_pairs(gas.boxes, pairs);
    EXPECT_EQ(pairs, expected_pairs(gas.boxes, {}));
    EXPECT_EQ(cache.grid_runs(), 1u);
    gas.step(1e-3, 0.6);
    gas.boxes.reach = 0.0;
    cache.find_pairs(gas.boxes, pairs);
    EXPECT_EQ(pairs, expected_pairs(gas.boxes, {}));
    EXPECT_EQ(cache.grid_runs(), 2u);
    EXPECT_GT(pairs.size(), 100u);
}

}  // namespace
}  // namespace pl::collide
