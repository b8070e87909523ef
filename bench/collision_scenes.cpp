#include "collision_scenes.hpp"

#include "physics/model/emitter.hpp"

#include <cmath>

namespace pl::bench {

CollisionScene dilute_gas(std::size_t n, bool collisions, double dt) {
    CollisionScene g;
    const double side = 2.0 * std::cbrt(static_cast<double>(n) / 1e4);
    g.model.room.size = {side, side, side};
    g.model.world.gravity = {0.0, 0.0, 0.0};
    g.model.contact = {1.0, 0.0, 0.0};
    g.model.integrator.dt = dt;
    g.model.collisions = {collisions, 1.0, 0.0};
    Emitter e;
    e.count = n;
    e.seed = 5;
    e.region_min = Vec3(-0.475 * side);
    e.region_max = Vec3(0.475 * side);
    e.speed_min = 0.5;
    e.speed_max = 2.0;
    e.radius_min = e.radius_max = 0.005;
    g.particles = emit_particles(e, g.model.room);
    return g;
}

CollisionScene pile(std::size_t n) {
    CollisionScene g;
    const double side = 0.04 * std::sqrt(static_cast<double>(n) / 10.0);
    g.model.room.center = {0.0, 1.0, 0.0};
    g.model.room.size = {side, 2.0, side};
    g.model.contact = {0.5, 0.5, 0.05};
    g.model.integrator.dt = 0.002;
    g.model.collisions = {true, 0.5, 0.5};
    Emitter e;
    e.count = n;
    e.seed = 1;
    e.region_min = {-side / 2 + 0.02, 0.1, -side / 2 + 0.02};
    e.region_max = {side / 2 - 0.02, 1.5, side / 2 - 0.02};
    e.speed_min = 0.0;
    e.speed_max = 0.5;
    e.radius_min = e.radius_max = 0.02;
    e.mass_min = e.mass_max = 0.03;
    g.particles = emit_particles(e, g.model.room);
    return g;
}

}  // namespace pl::bench
