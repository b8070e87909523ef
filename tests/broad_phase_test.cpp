// The collision broad phase (physics/collide/broad_phase.hpp) finds exactly the pairs that the
// all-pairs loop finds, with equal radii, mixed radii and a few big balls among small ones.
#include "physics/collide/broad_phase.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace pl::collide {
namespace {

// n spheres in a cube of side `side`, each moved by up to `motion` over the step.
SweptBoxes random_boxes(std::size_t n, double side, double r_min, double r_max, double motion, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> pos(0.0, side), rad(r_min, r_max), step(-motion, motion);
    SweptBoxes b;
    b.resize(n);
    for (std::uint32_t i = 0; i < n; ++i) {
        const double r = rad(rng);
        for (int k = 0; k < 3; ++k) {
            const double x0 = pos(rng) - 0.5 * side, x1 = x0 + step(rng);
            b.box[i].lo[k] = std::min(x0, x1) - r;
            b.box[i].hi[k] = std::max(x0, x1) + r;
        }
        b.ids.push_back(i);
    }
    return b;
}

void expect_same_pairs(const SweptBoxes& boxes, std::size_t at_least) {
    BroadPhase grid;
    std::vector<Pair> fast, slow;
    grid.find_pairs(boxes, fast);
    all_pairs(boxes, slow);
    EXPECT_EQ(fast, slow);
    EXPECT_GE(slow.size(), at_least) << "too few pairs for the comparison to mean much";
}

TEST(BroadPhase, EqualRadiiSameAsAllPairs) {
    const SweptBoxes boxes = random_boxes(3000, 1.0, 0.01, 0.01, 0.005, 1);
    expect_same_pairs(boxes, 200);
    BroadPhase grid;
    std::vector<Pair> pairs;
    grid.find_pairs(boxes, pairs);
    EXPECT_EQ(grid.big_count(), 0u);
}

TEST(BroadPhase, MixedRadiiSameAsAllPairs) { expect_same_pairs(random_boxes(3000, 1.0, 0.003, 0.02, 0.01, 2), 200); }

TEST(BroadPhase, FewBigBallsGoToTheirOwnList) {
    SweptBoxes boxes = random_boxes(3000, 1.0, 0.005, 0.005, 0.0, 3);
    for (std::uint32_t i : {7u, 1500u, 2999u})
        for (int k = 0; k < 3; ++k) {
            const double c = 0.5 * (boxes.box[i].lo[k] + boxes.box[i].hi[k]);
            boxes.box[i].lo[k] = c - 0.2;
            boxes.box[i].hi[k] = c + 0.2;
        }
    expect_same_pairs(boxes, 100);
    BroadPhase grid;
    std::vector<Pair> pairs;
    grid.find_pairs(boxes, pairs);
    EXPECT_EQ(grid.big_count(), 3u);
    EXPECT_LT(grid.cell_size(), 0.05);  // the grid stays fine for the small ones
}

TEST(BroadPhase, LeftOutParticlesHaveNoPairs) {
    SweptBoxes boxes = random_boxes(500, 0.3, 0.01, 0.01, 0.0, 4);
    boxes.ids.erase(boxes.ids.begin() + 100, boxes.ids.begin() + 200);  // as frozen particles are
    expect_same_pairs(boxes, 50);
    BroadPhase grid;
    std::vector<Pair> pairs;
    grid.find_pairs(boxes, pairs);
    for (const Pair& p : pairs) {
        EXPECT_FALSE(p.a >= 100 && p.a < 200);
        EXPECT_FALSE(p.b >= 100 && p.b < 200);
    }
}

TEST(BroadPhase, PairsOfTwoSleepingParticlesAreLeftOut) {
    // Every third particle awake, the rest asleep, and three big balls (one asleep) among them:
    // exactly the all-pairs loop's pairs that have an awake particle.
    SweptBoxes boxes = random_boxes(3000, 0.6, 0.01, 0.01, 0.002, 5);
    for (std::uint32_t i : {9u, 1500u, 2998u})
        for (int k = 0; k < 3; ++k) {
            const double c = 0.5 * (boxes.box[i].lo[k] + boxes.box[i].hi[k]);
            boxes.box[i].lo[k] = c - 0.15;
            boxes.box[i].hi[k] = c + 0.15;
        }
    std::vector<std::uint8_t> asleep(3000);
    for (std::uint32_t i = 0; i < 3000; ++i) asleep[i] = i % 3 != 0;
    BroadPhase grid;
    std::vector<Pair> fast, slow, expected;
    grid.find_pairs(boxes, fast, asleep.data());
    all_pairs(boxes, slow);
    for (const Pair& p : slow)
        if (!(asleep[p.a] && asleep[p.b])) expected.push_back(p);
    EXPECT_LT(grid.cell_size(), 0.05);  // the grid stays fine for the small ones
    EXPECT_EQ(fast, expected);
    EXPECT_GT(expected.size(), 500u);
    EXPECT_LT(expected.size(), slow.size());
}

TEST(BroadPhase, SameOnTwoThreadsAndAsTheCellAdapts) {
    // A dilute set (the cell grows over the calls, towards a few entries per cell) and a dense
    // one (it shrinks): every call, on one thread or two, gives the all-pairs loop's pairs.
    for (const double side : {4.0, 0.5}) {
        const SweptBoxes boxes = random_boxes(20000, side, 0.005, 0.005, 0.002, 6);
        std::vector<Pair> slow, one, two;
        all_pairs(boxes, slow);
        BroadPhase serial, threaded;
        std::vector<double> cells;
        for (int call = 0; call < 6; ++call) {
            serial.find_pairs(boxes, one, nullptr, 1);
            threaded.find_pairs(boxes, two, nullptr, 2);
            EXPECT_EQ(one, slow) << "side " << side << " call " << call;
            EXPECT_EQ(two, slow) << "side " << side << " call " << call;
            EXPECT_EQ(serial.cell_size(), threaded.cell_size());
            cells.push_back(serial.cell_size());
        }
        if (side > 1.0) EXPECT_GT(cells.back(), 2.0 * cells.front()) << "a dilute gas gets coarser cells";
        else EXPECT_LE(cells.back(), cells.front()) << "a dense crowd keeps fine cells";
        EXPECT_LT(serial.entry_count(), 8 * boxes.ids.size());
    }
}

TEST(BroadPhase, ManyCellsSortedInOnePassOnTwoThreads) {
    // 40,000 boxes over about 45^3 cells on the first call: the counting sort takes one pass,
    // its digit the whole cell, and over 8,192 cells the places of the cells' entries are
    // summed in chunks on the threads. The same pairs as on one thread, and near() (which reads
    // the cells' starts) finds every box a query meets.
    const SweptBoxes boxes = random_boxes(40000, 1.8, 0.008, 0.008, 0.004, 21);
    BroadPhase serial, threaded;
    std::vector<Pair> one, two;
    serial.find_pairs(boxes, one, nullptr, 1);
    threaded.find_pairs(boxes, two, nullptr, 2);
    const double cells = std::pow(1.8 / threaded.cell_size(), 3);
    ASSERT_GT(cells, 8192.0) << "the sort's digits must be many for the chunks to run";
    ASSERT_LT(cells, 131072.0) << "and fit one pass";
    EXPECT_EQ(one, two);
    EXPECT_GT(two.size(), 1000u);
    std::mt19937 rng(22);
    std::uniform_int_distribution<std::uint32_t> pick(0, 39999);
    for (int query = 0; query < 200; ++query) {
        const std::uint32_t i = pick(rng);
        std::vector<std::uint32_t> near;
        ASSERT_TRUE(threaded.near(boxes.box[i], near));
        std::sort(near.begin(), near.end());
        for (const Pair& p : two) {
            if (p.a != i && p.b != i) continue;
            EXPECT_TRUE(std::binary_search(near.begin(), near.end(), p.a == i ? p.b : p.a)) << "pair " << p.a << ", " << p.b;
        }
        EXPECT_TRUE(std::binary_search(near.begin(), near.end(), i)) << "a box meets itself";
    }
}

TEST(BroadPhase, BoxesThatMoveAndParticlesThatLeaveOverCalls) {
    // Each call enters the boxes in the order of the last call's cells. The boxes move between
    // calls (the order is stale), particles leave and come back (as frozen ones do: the order is
    // of other ids) and two grow big (they have no cell): every call still gives every pair.
    SweptBoxes boxes = random_boxes(12000, 1.2, 0.004, 0.01, 0.003, 8);
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> shift(-0.01, 0.01);
    BroadPhase serial, threaded;
    std::vector<Pair> slow, one, two;
    for (int call = 0; call < 8; ++call) {
        for (SweptBox& b : boxes.box)
            for (int k = 0; k < 3; ++k) {
                const double d = shift(rng);
                b.lo[k] += d;
                b.hi[k] += d;
            }
        if (call == 3) boxes.ids.erase(boxes.ids.begin() + 10, boxes.ids.begin() + 4000);
        if (call == 5) {
            boxes.ids.resize(boxes.box.size());
            for (std::uint32_t i = 0; i < boxes.ids.size(); ++i) boxes.ids[i] = i;
            for (const std::uint32_t i : {17u, 9000u})
                for (int k = 0; k < 3; ++k) boxes.box[i].hi[k] = boxes.box[i].lo[k] + 1.0;
        }
        all_pairs(boxes, slow);
        serial.find_pairs(boxes, one, nullptr, 1);
        threaded.find_pairs(boxes, two, nullptr, 2);
        EXPECT_EQ(one, slow) << "call " << call;
        EXPECT_EQ(two, slow) << "call " << call;
        EXPECT_GT(slow.size(), 300u);
    }
    EXPECT_EQ(serial.big_count(), 2u);
}

TEST(BroadPhase, VastRoomAndSharedCorners) {
    // Balls of 1 mm over a kilometre: 1e18 cells of the median box; the cells grow until their
    // index fits, and the pairs are still exact. Then boxes that touch exactly at their corners
    // and faces (on cell boundaries): each pair once.
    SweptBoxes vast = random_boxes(2000, 1000.0, 0.001, 0.001, 0.0, 7);
    for (int k = 0; k < 3; ++k) {  // one close pair among them
        vast.box[1].lo[k] = vast.box[0].lo[k] + 0.0015;
        vast.box[1].hi[k] = vast.box[0].hi[k] + 0.0015;
    }
    expect_same_pairs(vast, 1);
    SweptBoxes lattice;
    lattice.resize(512);
    for (std::uint32_t i = 0; i < 512; ++i) {
        const double c[3] = {0.1 * (i % 8), 0.1 * (i / 8 % 8), 0.1 * (i / 64)};
        for (int k = 0; k < 3; ++k) {
            lattice.box[i].lo[k] = c[k] - 0.05;
            lattice.box[i].hi[k] = c[k] + 0.05;
        }
        lattice.ids.push_back(i);
    }
    expect_same_pairs(lattice, 3 * 7 * 64);
}

TEST(BroadPhase, NearFindsEveryBoxAQueryMeets) {
    // After a call, near() lists (at least) every particle whose box meets the query box: in a
    // crowd, where the sort takes one pass and each row of cells is found from the cells'
    // starts, and in a vast room, where it takes several and each row is searched for. A query
    // spanning too many cells is refused; after a call with one box there is nothing to find.
    for (const double side : {1.0, 1000.0}) {
        const SweptBoxes boxes = random_boxes(3000, side, 0.005, 0.02, 0.01, 11);
        BroadPhase grid;
        std::vector<Pair> pairs;
        grid.find_pairs(boxes, pairs);
        std::mt19937 rng(12);
        std::uniform_int_distribution<std::uint32_t> pick(0, 2999);
        std::size_t met = 0;
        for (int query = 0; query < 300; ++query) {
            SweptBox q = boxes.box[pick(rng)];
            for (int k = 0; k < 3; ++k) q.hi[k] += 0.02;  // wider than its own box
            std::vector<std::uint32_t> near;
            ASSERT_TRUE(grid.near(q, near));
            std::sort(near.begin(), near.end());
            for (const std::uint32_t j : boxes.ids) {
                if (!overlap(q, boxes.box[j])) continue;
                ++met;
                EXPECT_TRUE(std::binary_search(near.begin(), near.end(), j)) << "side " << side << " particle " << j;
            }
        }
        EXPECT_GE(met, side < 10.0 ? 500u : 300u) << "side " << side;  // in the crowd, boxes meet others
        SweptBox huge;  // the whole room
        for (int k = 0; k < 3; ++k) {
            huge.lo[k] = -side;
            huge.hi[k] = side;
        }
        std::vector<std::uint32_t> near;
        EXPECT_FALSE(grid.near(huge, near)) << "side " << side << " cell " << grid.cell_size();
        EXPECT_TRUE(near.empty());
    }
    SweptBoxes one = random_boxes(1, 1.0, 0.01, 0.01, 0.0, 13);
    BroadPhase grid;
    std::vector<Pair> pairs;
    grid.find_pairs(random_boxes(3000, 1.0, 0.005, 0.02, 0.01, 11), pairs);
    grid.find_pairs(one, pairs);
    std::vector<std::uint32_t> near;
    EXPECT_TRUE(grid.near(one.box[0], near));
    EXPECT_TRUE(near.empty());
}

}  // namespace
}  // namespace pl::collide
