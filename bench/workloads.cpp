#include "workloads.hpp"

#include "physics/model/drag.hpp"
#include "physics/model/emitter.hpp"
#include "physics/stepping/thread_pool.hpp"

namespace pl::bench {

const char* to_string(Workload w) {
    switch (w) {
        case Workload::gravity: return "gravity";
        case Workload::drag_walls: return "drag_walls";
        case Workload::drag_walls_shear: return "drag_walls_shear";
        case Workload::drag_open: return "drag_open";
        case Workload::drag_rest: return "drag_rest";
    }
    return "?";
}

WorkloadScene make_workload(Workload w, std::size_t n, Method method) {
    WorkloadScene s;
    Model& m = s.model;
    m.label = to_string(w);
    m.room.center = {0.0, w == Workload::drag_open ? 500.0 : 3.0, 0.0};
    m.room.size = {10.0, 6.0, 10.0};
    m.contact.restitution = 0.8;
    m.contact.friction = 0.0;
    m.contact.rest_speed = 0.05;
    m.integrator.method = method;
    m.integrator.dt = 0.002;
    if (w != Workload::gravity) {
        m.drag.model = DragModel::quadratic;
        m.drag.cd = 0.47;
    }
    if (w == Workload::drag_walls_shear) {
        m.world.wind.kind = WindKind::shear;
        m.world.wind.velocity = {5.0, 0.0, 0.0};
        m.world.wind.reference_height_m = 2.0;
    }
    Emitter e;
    e.count = n;
    e.seed = 2024;
    e.region_min = m.room.min_corner();
    e.region_max = m.room.max_corner();
    e.speed_min = 0.0;
    e.speed_max = 5.0;
    e.spread_deg = 180.0;
    s.particles = emit_particles(e, m.room);
    if (w == Workload::drag_open) m.room.size = {1000.0, 1000.0, 1000.0};  // floor 497 m below the balls
    if (w == Workload::drag_rest) {
        m.contact.friction = 0.3;
        s.settle_steps = 5;
        for (ParticleSpec& p : s.particles) {
            p.position.y = m.room.min_corner().y + p.radius;
            p.velocity = Vec3(0.0);
        }
    }
    return s;
}

double workload_drag_constant(const Model& m, const ParticleSpec& p) {
    return drag_coefficients(m.drag, m.world.air, p.mass, p.radius).k;
}

std::vector<int> thread_settings() {
    std::vector<int> settings{1};
    if (hardware_threads() > 1) settings.push_back(hardware_threads());
    return settings;
}

std::string size_label(std::size_t n) {
    if (n >= 1000000 && n % 1000000 == 0) return std::to_string(n / 1000000) + "M";
    if (n >= 1000 && n % 1000 == 0) return std::to_string(n / 1000) + "k";
    return std::to_string(n);
}

}  // namespace pl::bench
