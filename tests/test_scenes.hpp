// Small scene builders shared by the physics tests.
#pragma once

#include "physics/model/emitter.hpp"
#include "physics/stepping/simulation.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace pl::test {

// A ball of radius r dropped from `height` (bottom of the ball above the floor) with no drag.
inline Model drop_model(double restitution, Method method, double dt, double rest_speed = 1e-3) {
    Model m;
    m.room.center = {0, 5, 0};
    m.room.size = {4, 10, 4};
    m.contact.restitution = restitution;
    m.contact.friction = 0.0;
    m.contact.rest_speed = rest_speed;
    m.integrator.method = method;
    m.integrator.dt = dt;
    return m;
}

inline ParticleSpec ball_at_height(double height, double radius = 0.05) {
    return {{0, height + radius, 0}, {0, 0, 0}, 0.1, radius};
}

// A 2 m room standing on y = 0 with collisions on: restitution e for the walls and between
// balls, friction `wall_friction` at the walls and `ball_friction` between balls.
inline Model colliding_room(double dt, Method method, double e, double wall_friction, double ball_friction) {
    Model m;
    m.room.center = {0.0, 1.0, 0.0};
    m.room.size = {2.0, 2.0, 2.0};
    m.contact.restitution = e;
    m.contact.friction = wall_friction;
    m.integrator.dt = dt;
    m.integrator.method = method;
    m.collisions.enabled = true;
    m.collisions.restitution = e;
    m.collisions.friction = ball_friction;
    return m;
}

struct Crowd {
    Model model;
    std::vector<ParticleSpec> particles;
};

// Many particles in a small room: plenty of bounces, rests and events in every range.
inline Crowd crowd(std::size_t n, Method method, DragModel drag, WindKind wind, std::uint64_t seed = 42) {
    Crowd c;
    c.model.room.size = {2.0, 2.0, 2.0};
    c.model.contact.restitution = 0.6;
    c.model.contact.friction = 0.4;
    c.model.contact.rest_speed = 0.3;
    c.model.integrator.method = method;
    c.model.integrator.dt = 0.004;
    c.model.drag.model = drag;
    c.model.world.wind.kind = wind;
    c.model.world.wind.velocity = {3.0, 0.0, -1.0};
    Emitter e;
    e.count = n;
    e.seed = seed;
    e.region_min = {-1, -1, -1};
    e.region_max = {1, 1, 1};
    e.speed_max = 8.0;
    e.radius_min = 0.01;
    e.radius_max = 0.08;
    e.mass_min = 0.01;
    e.mass_max = 0.3;
    c.particles = emit_particles(e, c.model.room);
    return c;
}

// Balls of 2 cm and 30 g, released at random (overlapping some) over a floor of `side` x
// `side` m, falling from up to `height` m; walls and pairs with e = 0.5, mu = 0.5.
struct Pile {
    Model model;
    std::vector<ParticleSpec> particles;
};

inline Pile pile(std::size_t n, double side, double height, std::uint64_t seed = 1) {
    Pile p;
    p.model.room.center = {0.0, height / 2, 0.0};
    p.model.room.size = {side, height, side};
    p.model.contact.restitution = 0.5;
    p.model.contact.friction = 0.5;
    p.model.contact.rest_speed = 0.05;
    p.model.integrator.dt = 0.002;
    p.model.collisions = {true, 0.5, 0.5};
    Emitter e;
    e.count = n;
    e.seed = seed;
    const double inner = side / 2 - 0.03;
    e.region_min = {-inner, 0.1 * height, -inner};
    e.region_max = {inner, 0.95 * height, inner};
    e.speed_min = 0.0;
    e.speed_max = 0.5;
    e.radius_min = e.radius_max = 0.02;
    e.mass_min = e.mass_max = 0.03;
    p.particles = emit_particles(e, p.model.room);
    return p;
}

// The deepest overlap of any pair, as a share of the smaller radius (all pairs: the reference).
inline double deepest_overlap(const ParticleState& s) {
    double worst = 0.0;
    for (std::size_t i = 0; i < s.size(); ++i)
        for (std::size_t j = i + 1; j < s.size(); ++j) {
            const double gap = glm::length(s.position(j) - s.position(i)) - s.radius[i] - s.radius[j];
            worst = std::max(worst, -gap / std::min(s.radius[i], s.radius[j]));
        }
    return worst;
}

inline std::vector<Event> of_kind(const std::vector<Event>& events, EventKind kind) {
    std::vector<Event> out;
    for (const Event& e : events)
        if (e.kind == kind) out.push_back(e);
    return out;
}

}  // namespace pl::test
