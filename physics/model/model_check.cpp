#include "physics/model/model_check.hpp"

#include "physics/model/air_model.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace pl {

namespace {

[[noreturn]] void fail(const std::string& field, const std::string& rule) {
    throw std::invalid_argument(field + ": " + rule);
}

void finite(const std::string& field, double x) {
    if (!std::isfinite(x)) fail(field, fmt::format("must be finite, got {}", x));
}

void finite(const std::string& field, const Vec3& v) {
    if (!(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z)))
        fail(field, fmt::format("must be finite, got [{}, {}, {}]", v.x, v.y, v.z));
}

void positive(const std::string& field, double x) {
    if (!(std::isfinite(x) && x > 0.0)) fail(field, fmt::format("must be finite and > 0, got {}", x));
}

void non_negative(const std::string& field, double x) {
    if (!(std::isfinite(x) && x >= 0.0)) fail(field, fmt::format("must be finite and >= 0, got {}", x));
}

void check_wind(const WindSettings& w) {
    finite("world.wind.velocity", w.velocity);
    switch (w.kind) {
        case WindKind::none:
        case WindKind::constant: break;
        case WindKind::gust:
            finite("world.wind.amplitude", w.gust_amplitude);
            positive("world.wind.period", w.gust_period_s);
            break;
        case WindKind::shear:
            positive("world.wind.reference_height", w.reference_height_m);
            finite("world.wind.exponent", w.shear_exponent);
            break;
        case WindKind::vortex:
            finite("world.wind.center", w.vortex_center);
            finite("world.wind.axis", w.vortex_axis);
            finite("world.wind.max_speed", w.vortex_max_speed);
            positive("world.wind.core_radius", w.vortex_core_radius_m);
            break;
    }
}

void check_particle(const Model& m, const ParticleSpec& p, std::size_t i) {
    const std::string at = fmt::format("particles[{}]", i);
    positive(at + ".mass", p.mass);
    positive(at + ".radius", p.radius);
    finite(at + ".position", p.position);
    finite(at + ".velocity", p.velocity);
    finite(at + ".spin", p.spin);
    if (p.inertia != Inertia::solid && p.inertia != Inertia::hollow)
        fail(at + ".inertia", "must be solid or hollow");
    const Vec3 lo = m.room.min_corner(), hi = m.room.max_corner();
    for (int a = 0; a < 3; ++a) {
        // The preset reader's tolerance for a sphere placed exactly on a wall (y = floor + radius).
        const double slack = 1e-12 * (std::abs(lo[a]) + std::abs(hi[a]) + p.radius);
        if (p.position[a] < lo[a] + p.radius - slack || p.position[a] > hi[a] - p.radius + slack)
            fail(at + ".position",
                 fmt::format("sphere (radius {}) at [{}, {}, {}] is not inside the room (it spans [{}, {}, {}] to "
                             "[{}, {}, {}]; the centre must stay a radius away from every wall)",
                             p.radius, p.position.x, p.position.y, p.position.z, lo.x, lo.y, lo.z, hi.x, hi.y, hi.z));
    }
}

}  // namespace

void check_model(const Model& m, const std::vector<ParticleSpec>& particles) {
    positive("integrator.dt", m.integrator.dt);
    if (m.integrator.method == Method::dopri5) {
        positive("integrator.rtol", m.integrator.rtol);
        positive("integrator.atol", m.integrator.atol);
    }
    finite("room.center", m.room.center);
    for (int a = 0; a < 3; ++a) positive(fmt::format("room.size[{}]", a), m.room.size[a]);
    finite("world.gravity", m.world.gravity);
    non_negative("world.air.density", m.world.air.density_kg_m3);
    non_negative("world.air.viscosity", m.world.air.viscosity_pa_s);
    if (m.world.air.model != AirModel::constant && m.world.air.model != AirModel::isa)
        fail("world.air.model", "must be constant or isa");
    if (m.world.air.model == AirModel::isa &&
        !(m.world.air.base_altitude_m >= min_base_altitude_m && m.world.air.base_altitude_m <= max_base_altitude_m))
        fail("world.air.base_altitude", fmt::format("must be in [{}, {}] m (the troposphere), got {}",
                                                    min_base_altitude_m, max_base_altitude_m, m.world.air.base_altitude_m));
    check_wind(m.world.wind);
    non_negative("drag.cd", m.drag.cd);
    if (m.drag.linear_b) non_negative("drag.b", *m.drag.linear_b);
    if (m.drag.lift != LiftModel::none) positive("drag.spin_decay", m.drag.spin_decay_s);
    if (!(m.contact.restitution >= 0.0 && m.contact.restitution <= 1.0))
        fail("contact.restitution", fmt::format("must be in [0, 1], got {}", m.contact.restitution));
    non_negative("contact.friction", m.contact.friction);
    non_negative("contact.rest_speed", m.contact.rest_speed);
    non_negative("contact.rolling_resistance", m.contact.rolling_resistance);
    if (m.contact.restitution_law != RestitutionLaw::constant)
        positive("contact.restitution_speed", m.contact.restitution_speed);
    for (std::size_t i = 0; i < particles.size(); ++i) check_particle(m, particles[i], i);
}

}  // namespace pl
