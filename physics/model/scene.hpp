// Scene: plain data describing one experiment (what the user set). Presets are this struct
// serialised; the GUI, CLI, tests and benchmarks all build scenes through it.
// SI units throughout, y is up.
#pragma once

#include "physics/model/expectation.hpp"

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace pl {

using Vec3 = glm::dvec3;

// Axis-aligned box room. The seed's cube spans -1..1 at size 2.
struct Room {
    Vec3 center{0.0, 0.0, 0.0};
    Vec3 size{10.0, 6.0, 10.0};

    Vec3 min_corner() const { return center - 0.5 * size; }
    Vec3 max_corner() const { return center + 0.5 * size; }
    double floor_y() const { return center.y - 0.5 * size.y; }
    friend bool operator==(const Room&, const Room&) = default;
};

// How the air's density and viscosity are found (physics/model/air_model.hpp): constant, the
// two fields below; isa, the International Standard Atmosphere at each particle's altitude.
enum class AirModel { constant, isa };

struct Air {
    double density_kg_m3 = 1.225;   // constant: ISA sea level
    double viscosity_pa_s = 1.81e-5;  // constant: dynamic viscosity at 15 C
    AirModel model = AirModel::constant;
    double base_altitude_m = 0.0;   // isa: geometric altitude of the room's floor above sea level
    friend bool operator==(const Air&, const Air&) = default;
};

enum class WindKind { none, constant, gust, shear, vortex };

// w(x, t). Only the fields of the chosen kind are used.
struct WindSettings {
    WindKind kind = WindKind::none;
    Vec3 velocity{0.0, 0.0, 0.0};  // constant: the wind; gust: the mean; shear: wind at reference_height
    // gust: w = velocity + amplitude * s(t), s a seeded sum of sinusoids bounded by [-1, 1]
    Vec3 gust_amplitude{1.0, 0.0, 1.0};
    double gust_period_s = 3.0;  // dominant period of the variation
    std::uint64_t gust_seed = 1;
    // shear (power-law boundary layer): |w| = |velocity| * (height / reference_height)^exponent
    double reference_height_m = 2.0;
    double shear_exponent = 1.0 / 7.0;  // Hellmann exponent, open terrain
    // vortex (Rankine): swirl about an axis through vortex_center; tangential speed rises
    // linearly to vortex_max_speed at core_radius, then falls off as 1/r.
    Vec3 vortex_center{0.0, 0.0, 0.0};
    Vec3 vortex_axis{0.0, 1.0, 0.0};
    double vortex_max_speed = 3.0;
    double vortex_core_radius_m = 1.0;
    friend bool operator==(const WindSettings&, const WindSettings&) = default;
};

struct World {
    Vec3 gravity{0.0, -9.81, 0.0};
    Air air;
    WindSettings wind;
    bool buoyancy = false;  // the displaced air's weight lifts each particle (terms/buoyancy.hpp)
    bool added_mass = false;  // each particle carries 1/2 rho V of air along (terms/air_column.hpp)
    friend bool operator==(const World&, const World&) = default;
};

enum class DragModel { none, linear, quadratic, sphere_re };

// Magnus lift coefficient C_L(S) of the spin parameter S = R |w| / |u| (terms/magnus.hpp).
enum class LiftModel { none, sawicki, nathan };

struct DragSettings {
    DragModel model = DragModel::none;
    double cd = 0.47;  // quadratic: constant drag coefficient (smooth sphere, subcritical)
    // linear: explicit coefficient b in N s/m; when absent, Stokes b = 6 pi mu R from the air.
    std::optional<double> linear_b;
    LiftModel lift = LiftModel::none;  // Magnus lift on spinning particles (terms/magnus.hpp)
    double spin_decay_s = 30.0;        // with lift: time constant of the spin's aerodynamic decay
    friend bool operator==(const DragSettings&, const DragSettings&) = default;
};

// How e depends on the impact speed v_n (contact.restitution_law; physics/model/restitution.hpp).
enum class RestitutionLaw { constant, viscoelastic };

struct ContactSettings {
    double restitution = 0.8;  // e on the normal velocity, 0..1 (viscoelastic: at restitution_speed)
    double friction = 0.3;     // Coulomb mu, >= 0
    double rest_speed = 0.05;  // rebound speed (m/s) below which a particle comes to rest
    // true: friction at the walls acts at the contact point and couples to the particle's spin, so
    // a sliding ball ends up rolling (stepping/spin_contact.hpp); false: the seed's point-mass friction.
    bool spin = false;
    double rolling_resistance = 0.0;  // with spin: c_rr, a rolling ball decelerates at c_rr times the press
    RestitutionLaw restitution_law = RestitutionLaw::constant;
    double restitution_speed = 1.0;  // viscoelastic: the impact speed (m/s) at which e = restitution
    friend bool operator==(const ContactSettings&, const ContactSettings&) = default;
};

// Particle-particle collisions (physics/collide/): off by default, and then no collision code runs.
struct CollisionSettings {
    bool enabled = false;
    double restitution = 0.9;  // e on the pair's normal relative velocity, 0..1
    double friction = 0.0;     // Coulomb mu between the two surfaces, >= 0
    friend bool operator==(const CollisionSettings&, const CollisionSettings&) = default;
};

enum class Method { explicit_euler, semi_implicit_euler, velocity_verlet, rk4, dopri5, exponential };

struct IntegratorSettings {
    Method method = Method::semi_implicit_euler;
    double dt = 0.002;   // fixed step, s
    double rtol = 1e-6;  // dopri5 only
    double atol = 1e-9;  // dopri5 only
    bool adaptive = true;  // dopri5: false takes exactly one Dormand-Prince step per dt
    friend bool operator==(const IntegratorSettings&, const IntegratorSettings&) = default;
};

// Moment of inertia of a sphere, I = k m R^2: solid k = 2/5, thin hollow shell k = 2/3.
enum class Inertia { solid, hollow };
double inertia_factor(Inertia shape);  // k

struct ParticleSpec {
    Vec3 position{0.0, 1.0, 0.0};
    Vec3 velocity{0.0, 0.0, 0.0};
    double mass = 0.057;     // kg (a tennis ball)
    double radius = 0.033;   // m
    Vec3 spin{0.0, 0.0, 0.0};  // angular velocity, rad/s (acts with drag.lift or contact.spin)
    Inertia inertia = Inertia::solid;
};

// Creates `count` particles, seeded and reproducible.
struct Emitter {
    std::size_t count = 0;
    std::uint64_t seed = 1;
    Vec3 region_min{-1.0, 0.0, -1.0};
    Vec3 region_max{1.0, 1.0, 1.0};
    double speed_min = 0.0, speed_max = 5.0;
    // Directions are uniform within `spread_deg` of `direction` (180 = all directions).
    Vec3 direction{0.0, 1.0, 0.0};
    double spread_deg = 180.0;
    double mass_min = 0.057, mass_max = 0.057;
    double radius_min = 0.033, radius_max = 0.033;
};

// A variant overrides whole sections of the scene. All variants start from the same particles.
struct Variant {
    std::string label;
    std::optional<DragSettings> drag;
    std::optional<WindSettings> wind;
    std::optional<Air> air;
    std::optional<ContactSettings> contact;
    std::optional<IntegratorSettings> integrator;
    std::optional<CollisionSettings> collisions;
};

struct Scene {
    std::string name = "Untitled";
    std::string description;
    Room room;
    World world;
    DragSettings drag;
    ContactSettings contact;
    CollisionSettings collisions;
    IntegratorSettings integrator;
    std::vector<ParticleSpec> particles;
    std::optional<Emitter> emitter;
    std::vector<Variant> variants;  // empty: the scene itself is the only variant
    std::vector<Expectation> expect;  // quantities worth watching, with their expected values
};

// The constant description one simulation runs: a scene with one variant applied.
struct Model {
    std::string label;
    Room room;
    World world;
    DragSettings drag;
    ContactSettings contact;
    IntegratorSettings integrator;
    CollisionSettings collisions;
    friend bool operator==(const Model&, const Model&) = default;
};

std::size_t variant_count(const Scene& scene);  // >= 1
Model model_for_variant(const Scene& scene, std::size_t variant);
// Whether some run of the scene collides: the scene's model with no variants, else the model of
// some variant (model_for_variant: a variant's collisions section replaces the scene's). The one
// definition the reader's check of packed starts and the resource estimate share.
bool collides_in_some_run(const Scene& scene);
// The explicit particles followed by the emitter's, identical for every variant.
std::vector<ParticleSpec> initial_particles(const Scene& scene);

const char* to_string(Method m);
const char* to_string(DragModel d);
const char* to_string(WindKind w);
const char* to_string(LiftModel l);
const char* to_string(Inertia i);
const char* to_string(RestitutionLaw l);
const char* to_string(AirModel a);
std::optional<Method> method_from_string(const std::string& s);
std::optional<DragModel> drag_model_from_string(const std::string& s);
std::optional<WindKind> wind_kind_from_string(const std::string& s);

// Order of accuracy of each method (used for reports and the stability guard).
int method_order(Method m);
// Largest stable h*k for linear decay a = -k v; +inf where unconditionally stable.
double method_stability_limit(Method m);
// The limit on dt * k the stability guard holds a scene's integrator to: the method's, but none
// (+inf) for adaptive Dormand-Prince, whose error control shortens its internal steps as the
// drag stiffens (a stiff scene it solves correctly is not unstable).
double stability_limit(const IntegratorSettings& integrator);
// Whether an elastic bounce keeps the energy: every method's flight is exact (to the root
// search's round-off) under a constant force, so a located impact state is exact, except
// explicit Euler's, which gains about g dt of speed on every bounce arc.
bool keeps_bounce_energy(Method m);
// Whether a step of the method is exact under a constant force (x1 = x0 + h v0 + a h^2 / 2,
// v1 = v0 + a h): velocity Verlet, RK4, Dormand-Prince and the exponential step (exactly without
// drag); not the two Euler methods, which take the step's forces as a kick at one end of it.
bool exact_under_constant_force(Method m);
// How far a step of the method moves a particle under a constant extra acceleration a held over
// the whole step, in units of a h^2: semi-implicit Euler's x1 = x0 + h v1 gives 1, explicit
// Euler's x1 = x0 + h v0 gives 0, and the others, exact for a constant force (x1 = x0 + h v0 +
// a h^2 / 2), give 1/2 (the exponential step too, exactly without drag). The contact solver's
// impulses act over the whole step: each particle's end position moves by this share of dv h,
// so that a particle held at rest stays where it is on every method.
double constant_push_share(Method m);

// Whether the particles' spin takes part in the motion (Magnus lift or contact coupled to spin);
// such a model runs on the generic kernel, which carries the spin.
inline bool spin_matters(const Model& m) { return m.drag.lift != LiftModel::none || m.contact.spin; }
// Whether the air changes along a particle's path or moves with it: ISA air (density and
// viscosity depend on the height) or added mass (the inertia is m + 1/2 rho V). Such a model's
// forces are evaluated through terms/air_column.hpp, which only the generic kernel carries.
inline bool air_column_matters(const Model& m) { return m.world.added_mass || m.world.air.model != AirModel::constant; }
// Whether the model needs the generic kernel: spin, a restitution that depends on the speed
// (the fast kernel's contact lanes apply a constant e), or the air column above.
inline bool needs_generic_kernel(const Model& m) {
    return spin_matters(m) || m.contact.restitution_law != RestitutionLaw::constant || air_column_matters(m);
}

}  // namespace pl
