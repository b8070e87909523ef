#include "physics/model/scene.hpp"

#include "physics/model/emitter.hpp"

#include <limits>

namespace pl {

std::size_t variant_count(const Scene& scene) {
    return scene.variants.empty() ? 1 : scene.variants.size();
}

Model model_for_variant(const Scene& scene, std::size_t variant) {
    Model m{scene.name, scene.room, scene.world, scene.drag, scene.contact, scene.integrator, scene.collisions};
    if (scene.variants.empty()) return m;
    const Variant& v = scene.variants.at(variant);
    m.label = v.label;
    if (v.drag) m.drag = *v.drag;
    if (v.wind) m.world.wind = *v.wind;
    if (v.air) m.world.air = *v.air;
    if (v.contact) m.contact = *v.contact;
    if (v.integrator) m.integrator = *v.integrator;
    if (v.collisions) m.collisions = *v.collisions;
    return m;
}

bool collides_in_some_run(const Scene& scene) {
    for (std::size_t v = 0; v < variant_count(scene); ++v)
        if (model_for_variant(scene, v).collisions.enabled) return true;
    return false;
}

std::vector<ParticleSpec> initial_particles(const Scene& scene) {
    std::vector<ParticleSpec> out = scene.particles;
    // Appended in place: a copy of the emitted particles would double the peak at millions.
    if (scene.emitter) append_emitted(*scene.emitter, scene.room, out);
    return out;
}

const char* to_string(Method m) {
    switch (m) {
        case Method::explicit_euler: return "explicit_euler";
        case Method::semi_implicit_euler: return "semi_implicit_euler";
        case Method::velocity_verlet: return "velocity_verlet";
        case Method::rk4: return "rk4";
        case Method::dopri5: return "dopri5";
        case Method::exponential: return "exponential";
    }
    return "?";
}

const char* to_string(DragModel d) {
    switch (d) {
        case DragModel::none: return "none";
        case DragModel::linear: return "linear";
        case DragModel::quadratic: return "quadratic";
        case DragModel::sphere_re: return "sphere_re";
    }
    return "?";
}

const char* to_string(WindKind w) {
    switch (w) {
        case WindKind::none: return "none";
        case WindKind::constant: return "constant";
        case WindKind::gust: return "gust";
        case WindKind::shear: return "shear";
        case WindKind::vortex: return "vortex";
    }
    return "?";
}

const char* to_string(LiftModel l) {
    switch (l) {
        case LiftModel::none: return "none";
        case LiftModel::sawicki: return "sawicki";
        case LiftModel::nathan: return "nathan";
    }
    return "?";
}

const char* to_string(Inertia i) {
    switch (i) {
        case Inertia::solid: return "solid";
        case Inertia::hollow: return "hollow";
    }
    return "?";
}

const char* to_string(RestitutionLaw l) {
    switch (l) {
        case RestitutionLaw::constant: return "constant";
        case RestitutionLaw::viscoelastic: return "viscoelastic";
    }
    return "?";
}

const char* to_string(AirModel a) {
    switch (a) {
        case AirModel::constant: return "constant";
        case AirModel::isa: return "isa";
    }
    return "?";
}

double inertia_factor(Inertia shape) { return shape == Inertia::hollow ? 2.0 / 3.0 : 2.0 / 5.0; }

std::optional<Method> method_from_string(const std::string& s) {
    for (Method m : {Method::explicit_euler, Method::semi_implicit_euler, Method::velocity_verlet,
                     Method::rk4, Method::dopri5, Method::exponential})
        if (s == to_string(m)) return m;
    return std::nullopt;
}

std::optional<DragModel> drag_model_from_string(const std::string& s) {
    for (DragModel d : {DragModel::none, DragModel::linear, DragModel::quadratic, DragModel::sphere_re})
        if (s == to_string(d)) return d;
    return std::nullopt;
}

std::optional<WindKind> wind_kind_from_string(const std::string& s) {
    for (WindKind w : {WindKind::none, WindKind::constant, WindKind::gust, WindKind::shear, WindKind::vortex})
        if (s == to_string(w)) return w;
    return std::nullopt;
}

int method_order(Method m) {
    switch (m) {
        case Method::explicit_euler: return 1;
        case Method::semi_implicit_euler: return 1;
        case Method::velocity_verlet: return 2;
        case Method::rk4: return 4;
        case Method::dopri5: return 5;
        case Method::exponential: return 1;
    }
    return 1;
}

bool exact_under_constant_force(Method m) {
    switch (m) {
        case Method::explicit_euler:
        case Method::semi_implicit_euler: return false;
        case Method::velocity_verlet:
        case Method::rk4:
        case Method::dopri5:
        case Method::exponential: return true;
    }
    return false;
}

double constant_push_share(Method m) {
    if (exact_under_constant_force(m)) return 0.5;
    return m == Method::semi_implicit_euler ? 1.0 : 0.0;  // x1 = x0 + h v1, or x0 + h v0
}

double method_stability_limit(Method m) {
    // Stability of y' = -k y: |R(-hk)| <= 1 on the negative real axis.
    switch (m) {
        case Method::explicit_euler: return 2.0;
        case Method::semi_implicit_euler: return 2.0;
        case Method::velocity_verlet: return 2.0;   // Heun-type velocity update: R = 1 - z + z^2/2
        case Method::rk4: return 2.785293563405282;
        case Method::dopri5: return 3.306250000000000;  // fixed-step real-axis bound; adaptive stays stable
        case Method::exponential: return std::numeric_limits<double>::infinity();
    }
    return 2.0;
}

double stability_limit(const IntegratorSettings& integrator) {
    if (integrator.method == Method::dopri5 && integrator.adaptive) return std::numeric_limits<double>::infinity();
    return method_stability_limit(integrator.method);
}

bool keeps_bounce_energy(Method m) { return m != Method::explicit_euler; }

}  // namespace pl
