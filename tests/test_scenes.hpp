// Small scene builders shared by the physics tests.
#pragma once

#include "physics/model/emitter.hpp"
#include "physics/stepping/simulation.hpp"

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

inline std::vector<Event> of_kind(const std::vector<Event>& events, EventKind kind) {
    std::vector<Event> out;
    for (const Event& e : events)
        if (e.kind == kind) out.push_back(e);
    return out;
}

}  // namespace pl::test
