// Golden determinism hashes (as Box2D's determinism test): every shipped preset and variant,
// every method on one scene, and the wind kinds on a crowd, run a fixed number of steps; the
// bits of the final state (positions, velocities, every ledger array, resting and frozen flags),
// of the event list and of the warnings are hashed and compared with constants computed by the
// engine before the force-term refactor (issue 24). A change that moves a single bit of any
// trajectory fails here; such a change must say why in its commit and re-pin the constant.
// Each case runs on one thread one step per call, and on two threads through step_n (several
// steps per kernel call): both must give the pinned hash.
// PL_GOLDEN_PRINT=1 prints the table of computed hashes (to re-pin after a deliberate change).
#include "io/preset_io.hpp"
#include "physics/stepping/simulation.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

namespace pl {
namespace {

// FNV-1a, 64 bits (Fowler, Noll, Vo), over the bytes of each value in a fixed order.
struct Fnv1a {
    std::uint64_t h = 0xcbf29ce484222325ull;
    void byte(std::uint8_t b) { h = (h ^ b) * 0x100000001b3ull; }
    void u64(std::uint64_t v) {
        for (int i = 0; i < 8; ++i) byte(static_cast<std::uint8_t>(v >> (8 * i)));
    }
    void f64(double v) { u64(std::bit_cast<std::uint64_t>(v)); }
    template <class A>
    void doubles(const A& a) {
        u64(a.size());
        for (const double v : a) f64(v);
    }
    template <class A>
    void bytes(const A& a) {
        u64(a.size());
        for (const std::uint8_t v : a) byte(v);
    }
};

std::uint64_t hash_result(const Simulation& sim) {
    const ParticleState& s = sim.state();
    Fnv1a f;
    for (const auto* a : {&s.x, &s.y, &s.z, &s.vx, &s.vy, &s.vz, &s.dissipated_bounce, &s.dissipated_friction,
                          &s.dissipated_drag, &s.wind_work, &s.initial_energy})
        f.doubles(*a);
    // The rotation, where it takes part (only then: the hashes pinned before it existed stay).
    if (spin_matters(sim.model()))
        for (const auto* a : {&s.wx, &s.wy, &s.wz, &s.dissipated_rolling}) f.doubles(*a);
    // The collisions' ledger and count, where they are on (only then: earlier pins stay).
    if (sim.model().collisions.enabled) {
        f.doubles(s.collision_work);
        f.u64(sim.collisions_total());
    }
    f.bytes(s.resting);
    f.bytes(s.frozen);
    f.u64(sim.events().size());
    for (const Event& e : sim.events()) {
        f.f64(e.t);
        f.u64(e.particle);
        f.u64(static_cast<std::uint64_t>(static_cast<std::int64_t>(e.wall)));
        f.byte(static_cast<std::uint8_t>(e.kind));
        f.f64(e.speed_in);
        f.f64(e.speed_out);
    }
    f.u64(sim.dropped_events());
    f.u64(sim.warnings().size());
    for (const Warning& w : sim.warnings()) {
        f.byte(static_cast<std::uint8_t>(w.kind));
        f.u64(w.particle);
        f.f64(w.t);
        f.f64(w.value);
    }
    f.u64(sim.step_count());
    return f.h;
}

Scene load(const std::string& file) {
    const LoadResult r = load_preset(std::string(PL_SOURCE_DIR) + "/presets/" + file);
    if (!r.ok()) ADD_FAILURE() << file << ": " << r.error_text();
    return r.scene.value_or(Scene{});
}

// The same 10000-particle emitter as many_particles.json, cut to 4096 particles: two ranges on
// two threads (ranges split at >= 2048 particles), and quick enough for every method.
Scene with_crowd(Scene scene) {
    Scene crowd = load("many_particles.json");
    scene.particles.clear();
    scene.emitter = crowd.emitter;
    scene.emitter->count = 4096;
    return scene;
}

struct Case {
    const char* name;  // preset file, or a description of the scene
    std::size_t variant;
    std::uint64_t steps;
    std::uint64_t hash;  // pinned: computed by the engine before the refactor
};

std::uint64_t run(const Scene& scene, std::size_t variant, std::uint64_t steps, int threads) {
    Simulation sim(model_for_variant(scene, variant), initial_particles(scene));
    sim.set_threads(threads);
    if (threads == 1) {
        for (std::uint64_t k = 0; k < steps; ++k) sim.step();
    } else {
        sim.step_n(steps);
    }
    return hash_result(sim);
}

void check(const Scene& scene, const Case& c) {
    const std::uint64_t one = run(scene, c.variant, c.steps, 1);
    const std::uint64_t two = run(scene, c.variant, c.steps, 2);
    if (std::getenv("PL_GOLDEN_PRINT"))
        std::printf("    {\"%s\", %zu, %llu, 0x%016llxull},\n", c.name, c.variant,
                    static_cast<unsigned long long>(c.steps), static_cast<unsigned long long>(one));
    EXPECT_EQ(one, c.hash) << c.name << " variant " << c.variant << " on 1 thread";
    EXPECT_EQ(two, c.hash) << c.name << " variant " << c.variant << " on 2 threads";
}

// Every shipped preset, every variant. Small scenes run long enough to bounce, rest and slide.
const Case preset_cases[] = {
    {"altitude_air.json", 0, 2500, 0x0930efc0c30064e7ull},
    {"altitude_air.json", 1, 2500, 0x3a717db4d4034637ull},
    {"curve_ball.json", 0, 2500, 0x6263837670ad232aull},
    {"curve_ball.json", 1, 2500, 0xd24a274744c1381full},
    {"curve_ball.json", 2, 2500, 0x47f0da0e336984a7ull},
    {"default.json", 0, 2500, 0xdb12f395ab44bf29ull},
    {"drag_models.json", 0, 2500, 0xb34155b1defd7a44ull},
    {"drag_models.json", 1, 2500, 0x6f47d85198f9b787ull},
    {"drag_models.json", 2, 2500, 0xfe99a80f28ae2026ull},
    {"drag_models.json", 3, 2500, 0xdac587ff9f352b52ull},
    {"drop_restitution_0.8.json", 0, 2500, 0xd2cbb1d69815f73aull},
    {"dt_ladder.json", 0, 2500, 0x70eb8c0cc3be868dull},
    {"dt_ladder.json", 1, 2500, 0x155dadb5dab07197ull},
    {"dt_ladder.json", 2, 2500, 0x4f61aa412f104235ull},
    {"dt_ladder.json", 3, 2500, 0xd346826676c79f49ull},
    {"dt_ladder.json", 4, 2500, 0x8bb2a6dd7ea465afull},
    {"feather_vs_ball.json", 0, 2500, 0x948f8e01fb2d1294ull},
    {"feather_vs_ball.json", 1, 2500, 0xce00cc0bcdbd7380ull},
    {"friction_slide.json", 0, 2500, 0xdd15bf4ab59f5cc5ull},
    {"granular_pile.json", 0, 100, 0x90907522e53164ceull},
    {"granular_pile.json", 1, 100, 0xbf008441a14b8f44ull},
    {"integrators.json", 0, 2500, 0x537d48657de5c3a1ull},
    {"integrators.json", 1, 2500, 0x4f61aa412f104235ull},
    {"integrators.json", 2, 2500, 0xcf87683fd51f74feull},
    {"integrators.json", 3, 2500, 0x87d41b4302fbfaf4ull},
    {"integrators.json", 4, 2500, 0x1671a6cf90b282c6ull},
    {"integrators.json", 5, 2500, 0x920f55b49777b5f2ull},
    {"launch_velocities.json", 0, 2500, 0xa642f164efb05db3ull},
    {"many_particles.json", 0, 500, 0xb663c42a81fb063full},
    {"newtons_cradle.json", 0, 2500, 0x881e45a94183db09ull},
    {"newtons_cradle.json", 1, 2500, 0xdd0eaf5433218703ull},
    {"newtons_cradle.json", 2, 2500, 0xf8cb045724cd4f5full},
    {"optimal_angle.json", 0, 2500, 0x2cac261951c0305eull},
    {"pool_break.json", 0, 2500, 0x173e223a76a09df3ull},
    {"pool_break.json", 1, 2500, 0xc993676b97588b97ull},
    {"poured_balls.json", 0, 50, 0xd6bfc220558015b2ull},
    {"restitution.json", 0, 2500, 0xc2830ef3be8674dbull},
    {"restitution.json", 1, 2500, 0xd2cbb1d69815f73aull},
    {"restitution.json", 2, 2500, 0x29bb291b5dd5ca29ull},
    {"slide_roll_stop.json", 0, 7000, 0xdc4f57b46bad2411ull},
    {"slide_roll_stop.json", 1, 7000, 0xb6ce72076c07c3aaull},
    {"spin_bounce.json", 0, 2500, 0x21f9b934afe90035ull},
    {"spin_bounce.json", 1, 2500, 0x182ee8c3d9af1bedull},
    {"steel_on_foam.json", 0, 2500, 0xb5b2511e8ab410e4ull},
    {"steel_on_foam.json", 1, 2500, 0x54cfd1de5fd373aaull},
    {"steel_on_foam.json", 2, 2500, 0xf73ef8b5b4d605edull},
    {"viscoelastic_bounce.json", 0, 2500, 0x14d50ca55d187415ull},
    {"viscoelastic_bounce.json", 1, 2500, 0xfe15812cc168327cull},
    {"wind_kinds.json", 0, 2500, 0xaf1fda171321aa98ull},
    {"wind_kinds.json", 1, 2500, 0x798233e9179c4b5cull},
    {"wind_kinds.json", 2, 2500, 0x20db4706c3838324ull},
    {"wind_kinds.json", 3, 2500, 0x2c5d7f197a458431ull},
    {"wind_kinds.json", 4, 2500, 0x25ff8861914502b1ull},
};

TEST(GoldenHash, EveryPresetAndVariant) {
    for (const Case& c : preset_cases) {
        const Scene scene = load(c.name);
        ASSERT_LT(c.variant, variant_count(scene)) << c.name;
        check(scene, c);
    }
}

TEST(GoldenHash, ShippedPresetsAreAllCovered) {
    std::size_t cases = 0, variants = 0;
    for (const auto& entry : std::filesystem::directory_iterator(std::string(PL_SOURCE_DIR) + "/presets")) {
        if (entry.path().extension() != ".json") continue;
        variants += variant_count(load(entry.path().filename().string()));
    }
    for (const Case& c : preset_cases) cases += c.variant == 0 ? 1 : 0;
    EXPECT_EQ(std::size(preset_cases), variants) << "a preset or variant without a golden hash";
    EXPECT_GT(cases, 0u);
}

// Each method on default.json (one ball, long), index = Method's value.
const std::uint64_t method_hashes[] = {
    0xd811f580c2203310ull, 0xdb12f395ab44bf29ull, 0x0001b758883bec5dull,
    0x1cfd20996ca5bc1full, 0xde98630b8b14f463ull, 0xea890d0aee6d817dull,
};
// Each method on default.json's room filled by the crowd emitter (fast path, two ranges).
const std::uint64_t method_crowd_hashes[] = {
    0xacbd07086bcf6b7eull, 0xaee6070532077df1ull, 0x4ac5419e9c13892full,
    0xc151893a1189e86aull, 0xa1810599475cc7f5ull, 0x2c13ab73234318bfull,
};

TEST(GoldenHash, EveryMethod) {
    const Scene base = load("default.json");
    for (int m = 0; m <= static_cast<int>(Method::exponential); ++m) {
        Scene scene = base;
        scene.integrator.method = static_cast<Method>(m);
        const std::string name = std::string("default.json ") + to_string(scene.integrator.method);
        check(scene, {name.c_str(), 0, 2500, method_hashes[m]});
        const std::string crowd = name + " crowd";
        check(with_crowd(scene), {crowd.c_str(), 0, 250, method_crowd_hashes[m]});
    }
}

// Each wind kind on the crowd (wind in the vectorised and the scalar flight, on two ranges),
// index = WindKind's value; with quadratic and linear drag (the wind acts through the drag).
const std::uint64_t wind_quadratic_hashes[] = {
    0xaee6070532077df1ull, 0x7c1ad6c043aa8254ull, 0x446dafb47838d7c4ull,
    0x769536b13221c6fbull, 0x598efe7fabcc9711ull,
};
const std::uint64_t wind_linear_hashes[] = {
    0x81444986b9b238bfull, 0x904bb47e6e6be1ffull, 0x9174057d03c2af3bull,
    0x5e7c49111d69eb23ull, 0x453e9a535315f90full,
};

TEST(GoldenHash, EveryWindKindOnACrowd) {
    const Scene base = with_crowd(load("wind_kinds.json"));
    for (int w = 0; w <= static_cast<int>(WindKind::vortex); ++w) {
        for (const DragModel d : {DragModel::quadratic, DragModel::linear}) {
            Scene scene = base;
            scene.variants.clear();
            scene.drag.model = d;
            // wind_kinds.json's variants are the kinds in WindKind's order.
            scene.world.wind = model_for_variant(base, static_cast<std::size_t>(w)).world.wind;
            EXPECT_EQ(scene.world.wind.kind, static_cast<WindKind>(w));
            const std::string name = std::string("crowd wind ") + to_string(scene.world.wind.kind) + " " + to_string(d);
            const std::uint64_t* pinned = d == DragModel::quadratic ? wind_quadratic_hashes : wind_linear_hashes;
            check(scene, {name.c_str(), 0, 250, pinned[w]});
        }
    }
}

}  // namespace
}  // namespace pl
