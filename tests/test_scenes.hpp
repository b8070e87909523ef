// Small scene builders shared by the physics tests.
#pragma once

#include "physics/simulation.hpp"

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

inline std::vector<Event> of_kind(const std::vector<Event>& events, EventKind kind) {
    std::vector<Event> out;
    for (const Event& e : events)
        if (e.kind == kind) out.push_back(e);
    return out;
}

}  // namespace pl::test
