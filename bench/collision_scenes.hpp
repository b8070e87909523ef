// The scenes the collision benchmarks step (collision_bench.cpp, collision_paired.cpp): a dilute
// elastic gas and a settling pile, each sized so that its cost per particle-step compares like
// with like across n.
#pragma once

#include "physics/model/scene.hpp"

#include <cstddef>
#include <vector>

namespace pl::bench {

struct CollisionScene {
    Model model;
    std::vector<ParticleSpec> particles;
};

// Balls of 5 mm at 0.5 to 2 m/s, e = 1, no friction, gravity or drag, in a box that holds 10,000
// of them in 2 m x 2 m x 2 m at every n (the same density, so the same collisions per
// particle-step).
CollisionScene dilute_gas(std::size_t n, bool collisions, double dt = 1e-3);

// n balls of 2 cm, 30 g dropped from up to 1.5 m onto a floor that holds about n / 10 of them
// side by side; e = 0.5, mu = 0.5 for walls and pairs, dt = 2 ms. The balls and coefficients are
// those of collision_pile_test's pile (tests/test_scenes.hpp), the room is not: here a fixed 2 m
// height and a floor that grows with n, so every size settles about ten layers deep.
CollisionScene pile(std::size_t n);

}  // namespace pl::bench
