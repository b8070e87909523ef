// Reads a preset document by iterating the format's rows (physics/model/schema/*_fields.hpp):
// every section is read by one generic function; the checks that span several fields (ranges in
// order, particles that fit the room, unique variant labels, at least one particle, variant
// sections starting from the scene's own) are the explicit code below the generic part.
#include "io/preset_reader.hpp"

#include "io/value_reader.hpp"
#include "physics/model/start_packing.hpp"
#include "physics/model/schema/scene_fields.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string_view>
#include <unordered_map>

namespace pl {
namespace {

using schema::ChildInfo;
using schema::Field;
using schema::SectionSchema;

// What reading one section found, per key (rows first, then the children, in table order).
struct SectionRead {
    bool is_object = false;
    std::uint64_t present = 0;
    std::uint64_t failed = 0;
    bool ok(int key) const { return (present >> key & 1u) && !(failed >> key & 1u); }
    bool fine(int key) const { return !(failed >> key & 1u); }  // absent, or read well
};

// A section's keys with their index, so that the unknown-key check is one hash look-up per key.
template <class S>
struct KeyTable {
    std::vector<std::string_view> keys;
    std::vector<bool> required;
    std::unordered_map<std::string_view, int> index;
    std::string expected;  // "a, b, c" for the unknown-key message

    static const KeyTable& get() {
        static const KeyTable table = [] {
            KeyTable t;
            for (const Field<S>& f : SectionSchema<S>::rows) t.add(f.info.key, f.info.required);
            SectionSchema<S>::children([&](const ChildInfo& c, auto&&...) { t.add(c.key, c.required); });
            return t;
        }();
        return table;
    }
    static int at(std::string_view key) { return get().index.at(key); }

private:
    void add(std::string_view key, bool is_required) {
        index.emplace(key, static_cast<int>(keys.size()));
        keys.push_back(key);
        required.push_back(is_required);
        expected += (expected.empty() ? "" : ", ") + std::string(key);
    }
};

template <class S>
bool read_field(ValueReader& r, const Field<S>& f, const PresetJson& v, const std::string& p, S& out) {
    using K = schema::FieldKind;
    const schema::FieldInfo& i = f.info;
    switch (i.kind) {
        case K::number: return r.number(v, p, out.*std::get<double S::*>(f.member), i.bounds);
        case K::vec3: return r.vec3(v, p, out.*std::get<Vec3 S::*>(f.member), i.bounds);
        case K::bounded_vec3: return r.bounded_vec3(v, p, out.*std::get<Vec3 S::*>(f.member), i.bounds.hi);
        case K::direction: return r.direction(v, p, out.*std::get<Vec3 S::*>(f.member), i.bounds);
        case K::unsigned_integer: return r.unsigned_integer(v, p, out.*std::get<std::uint64_t S::*>(f.member), i.max_integer);
        case K::boolean: return r.boolean(v, p, out.*std::get<bool S::*>(f.member));
        case K::string: return r.string(v, p, out.*std::get<std::string S::*>(f.member), i.non_empty);
        case K::optional_number: return r.optional_number(v, p, out.*std::get<std::optional<double> S::*>(f.member), i.bounds);
        case K::format_tag: return r.format_tag(v, p);
        case K::version_tag: return r.version_tag(v, p);
        case K::enumeration: {
            const auto& access = std::get<schema::EnumAccess<S>>(f.member);
            int value = access.get(out);
            if (!r.enumeration(v, p, value, i.names)) return false;
            access.set(out, value);
            return true;
        }
    }
    return false;
}

// A particle whose fit inside the room is checked once the room is known.
struct PendingFit {
    std::string path;
    Vec3 position;
    double radius;
};

class Reader : ValueReader {
public:
    explicit Reader(PresetErrorList& errors) : ValueReader(errors) {}

    void document(const PresetJson& doc, Scene& scene);

private:
    template <class S>
    SectionRead section(const PresetJson& j, const std::string& path, S& out);
    template <class S>
    bool child(int index, const PresetJson& v, const std::string& p, S& out);

    // One child section, by the shape of its member.
    template <class T>
    bool member_section(const ChildInfo&, const PresetJson& v, const std::string& p, T& out) {
        return section(v, p, out).is_object;
    }
    template <class T, class... Base>
    bool member_section(const ChildInfo&, const PresetJson& v, const std::string& p, std::optional<T>& out, Base... base) {
        // A variant's section starts from the scene's own, so it need only name what differs.
        if constexpr (sizeof...(Base) == 1) out = (base(*scene_), ...);
        else out.emplace();
        return section(v, p, *out).is_object;
    }
    template <class T>
    bool member_section(const ChildInfo& c, const PresetJson& v, const std::string& p, std::vector<T>& out) {
        if (!array(c, v, p)) return false;
        out.assign(v.size(), T{});
        for (std::size_t i = 0; i < v.size(); ++i) section(v[i], json_path_index(p, i), out[i]);
        return true;
    }
    bool member_section(const ChildInfo&, const PresetJson& v, const std::string&, std::vector<Variant>&) {
        variant_list_ = &v;  // read last: variant sections start from the scene's own
        return true;
    }
    bool array(const ChildInfo& c, const PresetJson& v, const std::string& p);

    // Cross-field checks, run after each section is read; most sections have none.
    template <class S>
    void checked(const SectionRead&, const std::string&, const S&) {}
    void checked(const SectionRead& r, const std::string& path, const Room& room);
    void checked(const SectionRead& r, const std::string& path, const ParticleSpec& s);
    void checked(const SectionRead& r, const std::string& path, const Emitter& e);
    void checked(const SectionRead& r, const std::string& path, const Expectation& e);
    void ordered(bool both_ok, double low, double high, const std::string& high_path, const std::string& low_name);

    void variants(const PresetJson& j, const std::string& path, Scene& scene);
    void particle_count(const SectionRead& r, const Scene& scene);
    void check_fits(const Room& room, const Scene& scene);
    void check_start_packing(const Scene& scene);
    void check_expectations(const Scene& scene);

    const Scene* scene_ = nullptr;
    const PresetJson* variant_list_ = nullptr;
    bool room_ok_ = false;
    bool emitter_radius_ok_ = false;
    bool emitter_count_ok_ = false;
    bool emitter_region_ok_ = false;
    std::vector<PendingFit> pending_fits_;
    std::vector<std::pair<std::string, Expectation>> pending_expectations_;  // indices checked at the end
};

// Visits an object's keys in document order; unknown keys are errors, missing required ones too.
template <class S>
SectionRead Reader::section(const PresetJson& j, const std::string& path, S& out) {
    SectionRead r;
    const KeyTable<S>& keys = KeyTable<S>::get();
    const auto rows = SectionSchema<S>::rows;
    if (!j.is_object()) {
        fail(path, "expected an object, got " + type_text(j));
    } else {
        r.is_object = true;
        for (const auto& item : j.items()) {
            const std::string p = json_path_key(path, item.key());
            const auto at = keys.index.find(item.key());
            if (at == keys.index.end()) {
                fail(p, "unknown key (expected one of " + keys.expected + ")");
                continue;
            }
            const int k = at->second;
            const int row_count = static_cast<int>(rows.size());
            r.present |= std::uint64_t{1} << k;
            const bool ok = k < row_count ? read_field(*this, rows[static_cast<std::size_t>(k)], item.value(), p, out)
                                          : child(k - row_count, item.value(), p, out);
            if (!ok) r.failed |= std::uint64_t{1} << k;
        }
        for (std::size_t k = 0; k < keys.keys.size(); ++k)
            if (keys.required[k] && !(r.present >> k & 1u))
                fail(json_path_key(path, std::string(keys.keys[k])), "required key is missing");
    }
    checked(r, path, out);
    return r;
}

template <class S>
bool Reader::child(int index, const PresetJson& v, const std::string& p, S& out) {
    bool ok = true;
    int n = 0;
    SectionSchema<S>::children([&](const ChildInfo& c, auto member, auto... base) {
        if (n++ == index) ok = member_section(c, v, p, out.*member, base...);
    });
    return ok;
}

bool Reader::array(const ChildInfo& c, const PresetJson& v, const std::string& p) {
    if (!v.is_array()) {
        fail(p, fmt::format("expected an array of {} objects, got {}", c.item_name, type_text(v)));
        return false;
    }
    if (v.size() > max_preset_particles) {
        fail(p, fmt::format("lists {} {}s; at most {} are allowed", v.size(), c.item_name, max_preset_particles));
        return false;
    }
    return true;
}

// ---------------------------------------------------------------- cross-field checks

void Reader::checked(const SectionRead& r, const std::string&, const Room&) {
    room_ok_ = r.is_object && r.ok(KeyTable<Room>::at("center")) && r.ok(KeyTable<Room>::at("size"));
}

void Reader::checked(const SectionRead& r, const std::string& path, const ParticleSpec& s) {
    if (r.is_object && r.ok(KeyTable<ParticleSpec>::at("position")) && r.fine(KeyTable<ParticleSpec>::at("radius")))
        pending_fits_.push_back({path, s.position, s.radius});
}

void Reader::checked(const SectionRead& r, const std::string& path, const Expectation& e) {
    if (r.is_object && r.fine(KeyTable<Expectation>::at("particle")) && r.fine(KeyTable<Expectation>::at("variant")))
        pending_expectations_.emplace_back(path, e);
}

// An expectation names a particle and a variant the scene has.
void Reader::check_expectations(const Scene& scene) {
    const std::size_t particles = scene.particles.size() + (scene.emitter ? scene.emitter->count : 0);
    const std::size_t variants = std::max<std::size_t>(1, scene.variants.size());
    for (const auto& [path, e] : pending_expectations_) {
        if (e.particle >= particles)
            fail(json_path_key(path, "particle"),
                 fmt::format("is {}, but the scene has {} particle{} (indices from 0)", e.particle, particles, particles == 1 ? "" : "s"));
        if (e.variant >= variants)
            fail(json_path_key(path, "variant"),
                 fmt::format("is {}, but the scene has {} variant{} (indices from 0)", e.variant, variants, variants == 1 ? "" : "s"));
    }
}

void Reader::ordered(bool both_ok, double low, double high, const std::string& high_path, const std::string& low_name) {
    if (both_ok && !(high >= low))
        fail(high_path, fmt::format("must be >= {} ({}), got {}", low_name, number_text(low), number_text(high)));
}

void Reader::checked(const SectionRead& r, const std::string& path, const Emitter& e) {
    const auto fine = [&](std::string_view key) { return r.fine(KeyTable<Emitter>::at(key)); };
    emitter_count_ok_ = r.ok(KeyTable<Emitter>::at("count"));
    if (!r.is_object) return;
    for (int a = 0; a < 3; ++a)
        ordered(fine("region_min") && fine("region_max"), e.region_min[a], e.region_max[a],
                json_path_index(json_path_key(path, "region_max"), static_cast<std::size_t>(a)),
                json_path_index("region_min", static_cast<std::size_t>(a)));
    ordered(fine("speed_min") && fine("speed_max"), e.speed_min, e.speed_max, json_path_key(path, "speed_max"), "speed_min");
    ordered(fine("mass_min") && fine("mass_max"), e.mass_min, e.mass_max, json_path_key(path, "mass_max"), "mass_min");
    ordered(fine("radius_min") && fine("radius_max"), e.radius_min, e.radius_max, json_path_key(path, "radius_max"),
            "radius_min");
    emitter_radius_ok_ = fine("radius_min") && fine("radius_max");
    emitter_region_ok_ = fine("region_min") && fine("region_max");
}

void Reader::variants(const PresetJson& j, const std::string& path, Scene& scene) {
    if (!array({"variants", "", false, "variant"}, j, path)) return;
    std::vector<Variant> read(j.size());
    for (std::size_t i = 0; i < j.size(); ++i) {
        const std::string p = json_path_index(path, i);
        section(j[i], p, read[i]);
        if (read[i].label.empty()) continue;
        for (std::size_t k = 0; k < i; ++k)
            if (read[k].label == read[i].label) {
                fail(json_path_key(p, "label"), "duplicate label " + quoted_for_message(read[i].label) +
                                                   " (already used by " + json_path_index(path, k) + ")");
                break;
            }
    }
    scene.variants = std::move(read);
}

void Reader::check_fits(const Room& room, const Scene& scene) {
    const double smallest = std::min({room.size.x, room.size.y, room.size.z});
    const Vec3 lo = room.min_corner(), hi = room.max_corner();
    for (const PendingFit& f : pending_fits_) {
        if (!(f.radius < 0.5 * smallest)) {
            fail(json_path_key(f.path, "radius"), fmt::format("must be < {} (half the room's smallest size), got {}",
                                                              number_text(0.5 * smallest), number_text(f.radius)));
            continue;
        }
        bool fits = true;
        for (int a = 0; a < 3; ++a) {
            // Tolerate rounding for a sphere placed exactly on a wall (e.g. y = floor + radius).
            const double slack = 1e-12 * (std::abs(lo[a]) + std::abs(hi[a]) + f.radius);
            if (f.position[a] < lo[a] + f.radius - slack || f.position[a] > hi[a] - f.radius + slack) fits = false;
        }
        if (!fits)
            fail(f.path, fmt::format("sphere (radius {}) does not fit inside the room at position {} "
                                     "(the room spans {} to {}; the centre must stay a radius away from every wall)",
                                     number_text(f.radius), vec_text(f.position), vec_text(lo), vec_text(hi)));
    }
    if (scene.emitter && emitter_radius_ok_ && !(scene.emitter->radius_max < 0.5 * smallest))
        fail("emitter.radius_max", fmt::format("must be < {} (half the room's smallest size), got {}",
                                               number_text(0.5 * smallest), number_text(scene.emitter->radius_max)));
}

// With collisions on in some run (collides_in_some_run: the scene's, or a variant's that replaces
// it), the balls may not start packed beyond the space they start in
// (physics/model/start_packing.hpp): the emitter's by their volume fraction, the listed ones' by
// their overlapping pairs. Without collisions overlaps cost nothing, and are allowed: a scene
// whose every variant turns collisions off never collides.
void Reader::check_start_packing(const Scene& scene) {
    if (!collides_in_some_run(scene)) return;
    const std::string most = number_text(max_start_volume_fraction);
    const Emitter* e = scene.emitter ? &*scene.emitter : nullptr;
    if (e && e->count >= 2 && emitter_radius_ok_ && emitter_count_ok_ && emitter_region_ok_) {
        const double fraction = emitted_volume_fraction(*e, scene.room);
        if (fraction > max_start_volume_fraction)
            fail("emitter.count",
                 fmt::format("with collisions on, {} balls (mean radius {} m) would have a volume fraction of {:.3g} in "
                             "the space they start in (the region of centres inside the room, grown by a radius; at "
                             "most {}): each would start inside others. Widen region_min/region_max, emit fewer or "
                             "smaller balls, or turn collisions off",
                             e->count, number_text(0.5 * (e->radius_min + e->radius_max)), fraction, most));
    }
    // Every listed particle read (each a pending fit): else its own errors come first.
    const std::vector<ParticleSpec>& listed = scene.particles;
    if (listed.size() >= 2 && pending_fits_.size() == listed.size()) {
        const OverlapCount overlaps = listed_overlaps(listed);
        if (overlaps.over_limit)
            fail("particles",
                 fmt::format("with collisions on, the {} listed balls overlap in more than {} pairs (at most {} per "
                             "ball): they start inside each other. The deepest seen, particles[{}] and particles[{}], "
                             "overlap by {} m, {:.3g} of their contact distance. Space them apart, or turn collisions off",
                             listed.size(), overlaps.pairs - 1, number_text(max_start_overlaps_per_ball),
                             overlaps.deepest_a, overlaps.deepest_b, number_text(overlaps.deepest_depth),
                             overlaps.deepest_share));
    }
}

void Reader::particle_count(const SectionRead& r, const Scene& scene) {
    const int list = KeyTable<Scene>::at("particles");
    const bool particles_present = r.present >> list & 1u;
    const bool emitter_ok = emitter_count_ok_;
    const std::size_t emitted = scene.emitter ? scene.emitter->count : 0;
    const std::size_t total = scene.particles.size() + emitted;
    if (total == 0 && (r.ok(list) || !particles_present) && (emitter_ok || !scene.emitter))
        fail("particles", "the preset has no particles: give a non-empty \"particles\" list or an \"emitter\" with count >= 1");
    if (total > max_preset_particles)
        fail("emitter.count", fmt::format("the preset would create {} particles ({} listed + {} emitted); at most {} are allowed",
                                          total, scene.particles.size(), emitted, max_preset_particles));
}

void Reader::document(const PresetJson& doc, Scene& scene) {
    if (!doc.is_object()) {
        fail("", "expected a JSON object at the top level, got " + type_text(doc));
        return;
    }
    scene_ = &scene;
    const SectionRead r = section(doc, "", scene);
    if (variant_list_) variants(*variant_list_, "variants", scene);
    particle_count(r, scene);
    if (room_ok_) check_fits(scene.room, scene);
    if (room_ok_) check_start_packing(scene);
    check_expectations(scene);
}

}  // namespace

void read_preset_document(const PresetJson& doc, Scene& scene, PresetErrorList& errors) {
    Reader(errors).document(doc, scene);
}

}  // namespace pl
