// Preset (de)serialisation: the shipped presets load, saved files load back identical, every
// field is written, and errors carry their JSON path.
#include "io/preset_io.hpp"
#include "physics/model/schema/scene_fields.hpp"

#include "preset_test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>
#include <unistd.h>

namespace pl {
namespace {

namespace fs = std::filesystem;
using TempDir = test::PresetTempDir;
using test::load_ok;
using test::preset_dir;
using test::read_bytes;

std::vector<fs::path> shipped_presets() {
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(preset_dir))
        if (entry.path().extension() == ".json") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

// Bitwise equality, so -0.0 vs 0.0 or a last-bit rounding difference shows up.
bool same(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }
bool same(const Vec3& a, const Vec3& b) { return same(a.x, b.x) && same(a.y, b.y) && same(a.z, b.z); }

bool same(const std::optional<double>& a, const std::optional<double>& b) {
    return a.has_value() == b.has_value() && (!a || same(*a, *b));
}
template <class T>
bool same(const T& a, const T& b) {
    return a == b;
}

// Field-by-field comparison over the preset rows (physics/model/schema/), reporting the first
// difference by its JSON path (empty when equal).
struct SceneDiff {
    std::string first;
    void check(bool equal, const std::string& field) {
        if (!equal && first.empty()) first = field;
    }
    template <class S>
    void section(const S& a, const S& b, const std::string& path) {
        const auto at = [&](const char* key) { return path.empty() ? std::string(key) : path + "." + key; };
        for (const schema::Field<S>& f : schema::SectionSchema<S>::rows)
            std::visit(
                [&](const auto& m) {
                    using M = std::remove_cvref_t<decltype(m)>;
                    if constexpr (std::is_same_v<M, schema::EnumAccess<S>>) check(m.get(a) == m.get(b), at(f.info.key));
                    else if constexpr (!std::is_same_v<M, std::monostate>) check(same(a.*m, b.*m), at(f.info.key));
                },
                f.member);
        schema::SectionSchema<S>::children(
            [&](const schema::ChildInfo& c, auto member, auto&&...) { child(a.*member, b.*member, at(c.key)); });
    }
    template <class T>
    void child(const T& a, const T& b, const std::string& p) {
        section(a, b, p);
    }
    template <class T>
    void child(const std::optional<T>& a, const std::optional<T>& b, const std::string& p) {
        check(a.has_value() == b.has_value(), p + " (presence)");
        if (a && b) section(*a, *b, p);
    }
    template <class T>
    void child(const std::vector<T>& a, const std::vector<T>& b, const std::string& p) {
        check(a.size() == b.size(), p + " (count)");
        for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) section(a[i], b[i], p + "[" + std::to_string(i) + "]");
    }
};

std::string scene_difference(const Scene& a, const Scene& b) {
    SceneDiff d;
    d.section(a, b, "");
    return d.first;
}

// A scene that uses every field with values whose decimal forms are awkward.
Scene awkward_scene() {
    Scene s;
    s.name = "Awkward \"quoted\" name \xC3\xA9\t\u00b0 \\ / \x01";
    s.description = "line one\nline two";
    s.room.center = {0.1 + 0.2, -1.0 / 3.0, 5e-324};
    s.room.size = {10.000000000000002, 6.0, 9.999999999999998};
    s.world.gravity = {1e-300, -9.80665, -0.0};
    s.world.air = {1.2250000000000001, 1.8100000000000002e-5};
    s.world.wind = {WindKind::vortex, {1.0 / 7.0, 0, 2.5}, {0.3, 0.0, 1e-17}, 2.718281828459045,
                    std::numeric_limits<std::uint64_t>::max(), 3.3, 0.14285714285714285, {0.5, -0.25, 1e5},
                    {1e-9, 1.0, 0.0}, 12.345678901234567, 0.75};
    s.drag = {DragModel::linear, 0.4700000000000001, 1e-7};
    s.contact = {0.95, 0.0, 0.0};
    s.integrator = {Method::dopri5, 1.0 / 1024.0, 1e-12, 1e-15, false};
    // The first particle touches three walls (centre exactly a radius from each).
    const Vec3 lo = s.room.min_corner(), hi = s.room.max_corner();
    s.particles = {{{lo.x + 0.033, lo.y + 0.033, hi.z - 0.033}, {99999.99999999999, -0.0, 1e-310}, 3.0000000000000004e-15, 0.033},
                   {{0.1 + 0.2, -1.0 / 3.0, 5e-324}, {3, 4, 1}, 1e6, 2.9999999999999996}};
    Emitter e;
    e.count = max_preset_particles - s.particles.size();
    e.seed = 0x9E3779B97F4A7C15ull;
    e.region_min = {-1e6, -0.1, -0.7};
    e.region_max = {1e6, 0.1, 0.7};
    e.speed_min = 0.1;
    e.speed_max = 0.1;
    e.direction = {1e-3, -1, 7};
    e.spread_deg = 179.99999999999997;
    e.mass_min = 0.001;
    e.mass_max = 0.0010000000000000002;
    e.radius_min = 1e-6;
    e.radius_max = 2.5;
    s.emitter = e;
    Variant v1;
    v1.label = "every section";
    v1.drag = DragSettings{DragModel::sphere_re, 0.3, std::nullopt};
    v1.wind = WindSettings{};
    v1.wind->kind = WindKind::gust;
    v1.air = Air{0.909, 1.69e-5};
    v1.contact = ContactSettings{0.0, 10.0, 1000.0};
    v1.integrator = IntegratorSettings{Method::exponential, 1.0, 1.0, 1.0, true};
    Variant v2;
    v2.label = "label only";
    s.variants = {v1, v2};
    return s;
}

// ---------------------------------------------------------------- shipped presets

TEST(ShippedPresets, AllLoadWithoutErrorsAndExplainThemselves) {
    const std::vector<fs::path> files = shipped_presets();
    ASSERT_GE(files.size(), 12u);
    for (const fs::path& file : files) {
        const Scene s = load_ok(file);
        EXPECT_FALSE(s.name.empty() || s.name == "Untitled") << file;
        EXPECT_GE(s.description.size(), 80u) << file << ": a description a student understands";
        EXPECT_FALSE(initial_particles(s).empty()) << file;
    }
}

TEST(ShippedPresets, DefaultIsTheBallThrownInARoom) {
    const Scene s = load_ok(preset_dir / "default.json");
    ASSERT_EQ(s.particles.size(), 1u);
    EXPECT_EQ(s.particles[0].velocity, Vec3(3, 4, 1));
    EXPECT_EQ(s.room.size, Vec3(10, 6, 10));
    EXPECT_EQ(s.contact.restitution, 0.8);
    EXPECT_EQ(s.contact.friction, 0.3);
    EXPECT_EQ(s.integrator.method, Method::semi_implicit_euler);
    EXPECT_EQ(s.integrator.dt, 0.002);
    EXPECT_EQ(s.drag.model, DragModel::quadratic);
    EXPECT_EQ(s.drag.cd, 0.47);
    EXPECT_EQ(s.world.air.density_kg_m3, 1.225);
    EXPECT_TRUE(s.variants.empty());
}

TEST(ShippedPresets, ComparisonPresetsHaveTheirVariants) {
    const Scene drag = load_ok(preset_dir / "drag_models.json");
    std::set<DragModel> models;
    for (std::size_t v = 0; v < variant_count(drag); ++v) models.insert(model_for_variant(drag, v).drag.model);
    EXPECT_EQ(models.size(), 4u);

    const Scene integrators = load_ok(preset_dir / "integrators.json");
    std::set<Method> methods;
    for (std::size_t v = 0; v < variant_count(integrators); ++v) {
        const Model m = model_for_variant(integrators, v);
        methods.insert(m.integrator.method);
        EXPECT_EQ(m.integrator.dt, 0.01) << m.label;
        EXPECT_EQ(m.drag.model, DragModel::quadratic);
    }
    EXPECT_EQ(methods.size(), 6u);

    const Scene ladder = load_ok(preset_dir / "dt_ladder.json");
    std::vector<double> dts;
    for (std::size_t v = 0; v < variant_count(ladder); ++v) {
        const Model m = model_for_variant(ladder, v);
        EXPECT_EQ(m.integrator.method, Method::semi_implicit_euler);
        dts.push_back(m.integrator.dt);
    }
    EXPECT_EQ(dts, (std::vector<double>{0.04, 0.02, 0.01, 0.005, 0.0025}));

    const Scene wind = load_ok(preset_dir / "wind_kinds.json");
    std::set<WindKind> kinds;
    for (std::size_t v = 0; v < variant_count(wind); ++v) kinds.insert(model_for_variant(wind, v).world.wind.kind);
    EXPECT_EQ(kinds.size(), 5u);

    const Scene restitution = load_ok(preset_dir / "restitution.json");
    std::vector<double> es;
    for (std::size_t v = 0; v < variant_count(restitution); ++v)
        es.push_back(model_for_variant(restitution, v).contact.restitution);
    EXPECT_EQ(es, (std::vector<double>{0.5, 0.8, 0.95}));

    const Scene altitude = load_ok(preset_dir / "altitude_air.json");
    ASSERT_EQ(variant_count(altitude), 2u);
    EXPECT_EQ(model_for_variant(altitude, 0).world.air.model, AirModel::isa);
    EXPECT_EQ(model_for_variant(altitude, 0).world.air.base_altitude_m, 0.0);
    EXPECT_EQ(model_for_variant(altitude, 1).world.air.model, AirModel::isa);
    EXPECT_EQ(model_for_variant(altitude, 1).world.air.base_altitude_m, 3000.0);
}

TEST(ShippedPresets, DropStartsTwoMetresAboveTheFloor) {
    const Scene s = load_ok(preset_dir / "drop_restitution_0.8.json");
    ASSERT_EQ(s.particles.size(), 1u);
    const ParticleSpec& p = s.particles[0];
    EXPECT_NEAR(p.position.y - p.radius - s.room.floor_y(), 2.0, 1e-12);
    EXPECT_EQ(p.velocity, Vec3(0.0));
    EXPECT_EQ(s.contact.restitution, 0.8);
    EXPECT_EQ(s.drag.model, DragModel::none);
}

TEST(ShippedPresets, ManyParticlesEmitsTenThousandInsideTheRoom) {
    const Scene s = load_ok(preset_dir / "many_particles.json");
    ASSERT_TRUE(s.emitter.has_value());
    const std::vector<ParticleSpec> particles = initial_particles(s);
    ASSERT_EQ(particles.size(), 10000u);
    const Vec3 lo = s.room.min_corner(), hi = s.room.max_corner();
    for (const ParticleSpec& p : particles)
        for (int a = 0; a < 3; ++a) {
            ASSERT_GE(p.position[a], lo[a] + p.radius);
            ASSERT_LE(p.position[a], hi[a] - p.radius);
        }
}

// ---------------------------------------------------------------- round trip

TEST(PresetRoundTrip, EveryShippedPresetSavesAndLoadsBackIdentical) {
    TempDir dir;
    for (const fs::path& file : shipped_presets()) {
        const Scene original = load_ok(file);
        const fs::path copy = dir.path / file.filename();
        const SaveResult saved = save_preset(copy, original);
        ASSERT_TRUE(saved.ok) << saved.error;
        const Scene reloaded = load_ok(copy);
        EXPECT_EQ(scene_difference(original, reloaded), "") << file;
        EXPECT_EQ(serialize_preset(reloaded), read_bytes(copy)) << file;
    }
}

TEST(PresetRoundTrip, AwkwardDoublesStringsAndSeedsSurviveBitForBit) {
    const Scene original = awkward_scene();
    const std::string text = serialize_preset(original);
    const LoadResult r = parse_preset(text);
    ASSERT_TRUE(r.ok()) << r.error_text() << "\n" << text;
    EXPECT_EQ(scene_difference(original, *r.scene), "");
    EXPECT_EQ(serialize_preset(*r.scene), text);
}

TEST(PresetRoundTrip, SceneDiffNamesTheFirstDifferentFieldByItsPath) {
    // Guards the comparison the round-trip tests rely on: it walks every row, optional section and list.
    Scene a;
    a.particles.push_back(ParticleSpec{});
    a.variants.push_back(Variant{"v", DragSettings{}, {}, {}, {}, {}, {}});
    Scene b = a;
    EXPECT_EQ(scene_difference(a, b), "");
    b.world.wind.gust_seed = 2;
    EXPECT_EQ(scene_difference(a, b), "world.wind.seed");
    b = a;
    b.variants[0].drag->linear_b = 0.5;
    EXPECT_EQ(scene_difference(a, b), "variants[0].drag.b");
    b = a;
    b.particles[0].mass = 1.0;
    EXPECT_EQ(scene_difference(a, b), "particles[0].mass");
    b = a;
    b.emitter.emplace();
    EXPECT_EQ(scene_difference(a, b), "emitter (presence)");
    b = a;
    b.integrator.method = Method::rk4;
    EXPECT_EQ(scene_difference(a, b), "integrator.method");
}

TEST(PresetRoundTrip, DefaultSceneRoundTrips) {
    Scene s;
    s.particles.push_back(ParticleSpec{});
    const LoadResult r = parse_preset(serialize_preset(s));
    ASSERT_TRUE(r.ok()) << r.error_text();
    EXPECT_EQ(scene_difference(s, *r.scene), "");
}

// ---------------------------------------------------------------- format details

TEST(PresetFormat, SavedFilesListEveryFieldIncludingDefaults) {
    Scene s;
    s.particles.push_back(ParticleSpec{});
    const std::string text = serialize_preset(s);
    for (const char* key : {"\"format\": \"particle-lab-preset\"", "\"version\": 1", "\"name\"", "\"description\"",
                            "\"center\"", "\"size\"", "\"gravity\"", "\"density\"", "\"viscosity\"", "\"kind\": \"none\"",
                            "\"velocity\"", "\"amplitude\"", "\"period\"", "\"seed\"", "\"reference_height\"",
                            "\"exponent\"", "\"axis\"", "\"max_speed\"", "\"core_radius\"", "\"model\": \"none\"",
                            "\"cd\"", "\"restitution\"", "\"friction\"", "\"rest_speed\"",
                            "\"method\": \"semi_implicit_euler\"", "\"dt\"", "\"rtol\"", "\"atol\"", "\"adaptive\"",
                            "\"position\"", "\"mass\"", "\"radius\"", "\"variants\": []"})
        EXPECT_NE(text.find(key), std::string::npos) << key << " missing from\n" << text;
    EXPECT_NE(text.find("\"b\": null"), std::string::npos) << "unset b (Stokes) is written as null";
}

TEST(PresetFormat, PrettyPrintedWithTwoSpaceIndent) {
    Scene s;
    s.particles.push_back(ParticleSpec{});
    const std::string text = serialize_preset(s);
    EXPECT_EQ(text.rfind("{\n  \"format\"", 0), 0u) << text;
    EXPECT_NE(text.find("\n  \"room\": "), std::string::npos);
    EXPECT_NE(text.find("\n    \"gravity\": [0.0, -9.81, 0.0]"), std::string::npos) << text;
    EXPECT_EQ(text.back(), '\n');
    EXPECT_EQ(text.find('\t'), std::string::npos);
}

TEST(PresetFormat, OmittedSectionsAndFieldsTakeTheSceneDefaults) {
    const LoadResult r = parse_preset(R"({ "format": "particle-lab-preset", "version": 1,
        "room": { "center": [0, 0, 0], "size": [10, 6, 10] },
        "particles": [ { "position": [0, 1, 0] } ] })");
    ASSERT_TRUE(r.ok()) << r.error_text();
    Scene expected;
    expected.particles.push_back(ParticleSpec{});
    EXPECT_EQ(scene_difference(expected, *r.scene), "");
}

TEST(PresetFormat, VariantSectionsStartFromTheScenesOwnSection) {
    const LoadResult r = parse_preset(R"({ "variants": [ { "label": "fine", "integrator": { "dt": 0.0005 } },
                                                        { "label": "no friction", "contact": { "friction": 0 } } ],
        "format": "particle-lab-preset", "version": 1,
        "room": { "center": [0, 0, 0], "size": [10, 6, 10] },
        "integrator": { "method": "rk4", "dt": 0.01 },
        "contact": { "restitution": 0.5 },
        "particles": [ { "position": [0, 1, 0] } ] })");
    ASSERT_TRUE(r.ok()) << r.error_text();
    const Scene& s = *r.scene;
    ASSERT_EQ(s.variants.size(), 2u);
    EXPECT_EQ(s.variants[0].integrator->method, Method::rk4);
    EXPECT_EQ(s.variants[0].integrator->dt, 0.0005);
    EXPECT_FALSE(s.variants[0].contact.has_value());
    EXPECT_EQ(s.variants[1].contact->restitution, 0.5);
    EXPECT_EQ(s.variants[1].contact->friction, 0.0);
}

TEST(PresetFormat, LinearDragCoefficientIsOptional) {
    const std::string head = R"({ "format": "particle-lab-preset", "version": 1,
        "room": { "center": [0, 0, 0], "size": [10, 6, 10] }, "particles": [ { "position": [0, 1, 0] } ], )";
    const LoadResult stokes = parse_preset(head + R"("drag": { "model": "linear" } })");
    ASSERT_TRUE(stokes.ok()) << stokes.error_text();
    EXPECT_FALSE(stokes.scene->drag.linear_b.has_value());
    const LoadResult explicit_b = parse_preset(head + R"("drag": { "model": "linear", "b": 0.02 } })");
    ASSERT_TRUE(explicit_b.ok()) << explicit_b.error_text();
    EXPECT_EQ(explicit_b.scene->drag.linear_b, 0.02);
    // A variant can go back to Stokes with an explicit null.
    const LoadResult variant = parse_preset(head + R"("drag": { "model": "linear", "b": 0.02 },
        "variants": [ { "label": "Stokes", "drag": { "b": null } }, { "label": "same b", "drag": {} } ] })");
    ASSERT_TRUE(variant.ok()) << variant.error_text();
    EXPECT_FALSE(variant.scene->variants[0].drag->linear_b.has_value());
    EXPECT_EQ(variant.scene->variants[1].drag->linear_b, 0.02);
}

TEST(PresetFormat, WholeNumberFloatsAreAcceptedForCountsAndSeeds) {
    const LoadResult r = parse_preset(R"({ "format": "particle-lab-preset", "version": 1,
        "room": { "center": [0, 0, 0], "size": [10, 6, 10] },
        "emitter": { "count": 1e3, "seed": 18446744073709551615 } })");
    ASSERT_TRUE(r.ok()) << r.error_text();
    EXPECT_EQ(r.scene->emitter->count, 1000u);
    EXPECT_EQ(r.scene->emitter->seed, std::numeric_limits<std::uint64_t>::max());
}

TEST(PresetFormat, ASphereRestingExactlyOnTheFloorFits) {
    const LoadResult r = parse_preset(R"({ "format": "particle-lab-preset", "version": 1,
        "room": { "center": [0.1, 0.2, 0.3], "size": [10, 6, 10] },
        "particles": [ { "position": [-4.867, -2.767, 5.267], "radius": 0.033 } ] })");
    EXPECT_TRUE(r.ok()) << r.error_text();
}

// ---------------------------------------------------------------- errors

}  // namespace
}  // namespace pl
