#include "io/preset_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <limits>
#include <string_view>

namespace pl {

// ------------------------------------------------------------------ errors and paths

void PresetErrorList::add(std::string path, std::string message) {
    if (message.ends_with("got null") &&
        std::find(blanked_paths_.begin(), blanked_paths_.end(), path) != blanked_paths_.end())
        return;
    if (errors_.size() < limit_)
        errors_.push_back({std::move(path), std::move(message)});
    else
        ++suppressed_;
}

std::vector<PresetError> PresetErrorList::take() {
    std::vector<PresetError> out = std::move(errors_);
    if (suppressed_ > 0) out.push_back({"", fmt::format("... and {} more errors not shown", suppressed_)});
    errors_.clear();
    suppressed_ = 0;
    return out;
}

namespace {

bool is_identifier(const std::string& key) {
    if (key.empty() || (key[0] >= '0' && key[0] <= '9')) return false;
    return std::all_of(key.begin(), key.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '$';
    });
}

}  // namespace

std::string quoted_for_message(const std::string& text) {
    constexpr std::size_t max_chars = 64;
    std::string shown = text.size() > max_chars ? text.substr(0, max_chars) : text;
    // Cutting may split a UTF-8 sequence; `replace` turns the stray bytes into U+FFFD.
    std::string out = PresetJson(shown).dump(-1, ' ', false, PresetJson::error_handler_t::replace);
    if (text.size() > max_chars) out += "...";
    return out;
}

std::string json_path_key(const std::string& parent, const std::string& key) {
    if (!is_identifier(key)) return parent + "[" + quoted_for_message(key) + "]";
    return parent.empty() ? key : parent + "." + key;
}

std::string json_path_index(const std::string& parent, std::size_t index) {
    return parent + "[" + std::to_string(index) + "]";
}

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

// Sane limits: far beyond any lab experiment, small enough that products of them stay finite.
constexpr double max_coordinate_m = 1e6;
constexpr double max_room_size_m = 1e6;
constexpr double max_speed_mps = 1e5;
constexpr double max_gravity_mps2 = 1e4;
constexpr double max_mass_kg = 1e6;
// Lightest particle: about a 1 um dust grain (4e-15 kg). Lighter ones are Brownian, outside this
// model, and a mass such as 5e-324 made the drag stiffness infinite (the particle froze).
constexpr double min_mass_kg = 1e-15;
constexpr double max_density_kg_m3 = 1e5;
constexpr double max_viscosity_pa_s = 1e3;
constexpr double max_cd = 100.0;
constexpr double max_linear_b = 1e6;
constexpr double max_friction = 10.0;
constexpr double max_rest_speed_mps = 1e3;
constexpr double max_dt_s = 1.0;
constexpr double max_tolerance = 1.0;
constexpr double max_period_s = 1e6;

// A closed/open interval a number must lie in. `interval` selects the message form
// "must be in [0, 1]" over the one-sided "must be > 0" / "must be <= 1".
struct Bounds {
    double lo = -inf;
    bool lo_open = false;
    double hi = inf;
    bool hi_open = false;
    bool interval = false;
};

constexpr Bounds any_finite() { return {}; }
constexpr Bounds positive(double hi) { return {0.0, true, hi, false, false}; }
constexpr Bounds non_negative(double hi) { return {0.0, false, hi, false, false}; }
constexpr Bounds symmetric(double limit) { return {-limit, false, limit, false, false}; }
constexpr Bounds closed(double lo, double hi) { return {lo, false, hi, false, true}; }

std::string number_text(double x) { return fmt::format("{}", x); }
std::string vec_text(const Vec3& v) { return fmt::format("[{}, {}, {}]", v.x, v.y, v.z); }

std::string type_text(const PresetJson& v) {
    if (v.is_number()) return "number";
    if (v.is_boolean()) return "boolean";
    return v.type_name();  // string, array, object, null
}

std::string join(std::initializer_list<std::string_view> names) {
    std::string out;
    for (std::string_view n : names) {
        if (!out.empty()) out += ", ";
        out += n;
    }
    return out;
}

bool contains(std::initializer_list<std::string_view> names, std::string_view key) {
    return std::find(names.begin(), names.end(), key) != names.end();
}

template <class E, std::size_t N>
std::string enum_names(const std::array<E, N>& values) {
    std::string out;
    for (E e : values) {
        if (!out.empty()) out += ", ";
        out += to_string(e);
    }
    return out;
}

constexpr std::array all_methods{Method::explicit_euler, Method::semi_implicit_euler, Method::velocity_verlet,
                                 Method::rk4,            Method::dopri5,              Method::exponential};
constexpr std::array all_drag_models{DragModel::none, DragModel::linear, DragModel::quadratic, DragModel::sphere_re};
constexpr std::array all_wind_kinds{WindKind::none, WindKind::constant, WindKind::gust, WindKind::shear,
                                    WindKind::vortex};

// A particle whose fit inside the room is checked once the room is known.
struct PendingFit {
    std::string path;
    Vec3 position;
    double radius;
};

// Reads one document. Every reader reports what is wrong and returns whether the value it
// produced is usable for later cross-checks; an absent optional field keeps its default.
class Reader {
public:
    explicit Reader(PresetErrorList& errors) : errors_(errors) {}

    void document(const PresetJson& doc, Scene& scene);

private:
    using FieldHandler = std::function<void(const std::string& key, const PresetJson& value, const std::string& path)>;

    void fail(const std::string& path, std::string message) { errors_.add(path, std::move(message)); }

    // Visits an object's fields in document order; unknown keys are errors.
    bool fields(const PresetJson& j, const std::string& path, std::initializer_list<std::string_view> known,
                const FieldHandler& handle) {
        if (!j.is_object()) {
            fail(path, "expected an object, got " + type_text(j));
            return false;
        }
        for (const auto& item : j.items()) {
            const std::string child = json_path_key(path, item.key());
            if (contains(known, item.key()))
                handle(item.key(), item.value(), child);
            else
                fail(child, "unknown key (expected one of " + join(known) + ")");
        }
        return true;
    }

    void require(const PresetJson& j, const std::string& path, std::initializer_list<std::string_view> keys) {
        if (!j.is_object()) return;
        for (std::string_view key : keys)
            if (!j.contains(key)) fail(json_path_key(path, std::string(key)), "required key is missing");
    }

    bool number(const PresetJson& v, const std::string& path, double& out, Bounds b) {
        if (!v.is_number()) {
            fail(path, "expected a number, got " + type_text(v));
            return false;
        }
        const double x = v.get<double>();
        if (!std::isfinite(x)) {
            // JSON has no NaN or Inf; an overflowing literal such as 1e400 reads as infinity.
            fail(path, "must be finite, but the number is too large for a double");
            return false;
        }
        const bool below = b.lo_open ? !(x > b.lo) : !(x >= b.lo);
        const bool above = b.hi_open ? !(x < b.hi) : !(x <= b.hi);
        if (!below && !above) {
            out = x;
            return true;
        }
        if (b.interval)
            fail(path, fmt::format("must be in {}{}, {}{}, got {}", b.lo_open ? "(" : "[", number_text(b.lo),
                                   number_text(b.hi), b.hi_open ? ")" : "]", number_text(x)));
        else if (below)
            fail(path, fmt::format("must be {} {}, got {}", b.lo_open ? ">" : ">=", number_text(b.lo), number_text(x)));
        else
            fail(path, fmt::format("must be {} {}, got {}", b.hi_open ? "<" : "<=", number_text(b.hi), number_text(x)));
        return false;
    }

    bool vec3(const PresetJson& v, const std::string& path, Vec3& out, Bounds b) {
        if (!v.is_array() || v.size() != 3) {
            fail(path, "expected an array of 3 numbers, got " +
                           (v.is_array() ? fmt::format("an array of {} elements", v.size()) : type_text(v)));
            return false;
        }
        Vec3 read = out;
        bool ok = true;
        for (std::size_t i = 0; i < 3; ++i) ok = number(v[i], json_path_index(path, i), read[static_cast<int>(i)], b) && ok;
        if (ok) out = read;
        return ok;
    }

    // A vector whose length is limited (velocities, amplitudes).
    bool bounded_vec3(const PresetJson& v, const std::string& path, Vec3& out, double max_length) {
        Vec3 read = out;
        if (!vec3(v, path, read, any_finite())) return false;
        const double length = glm::length(read);
        if (!(length <= max_length)) {
            fail(path, fmt::format("magnitude must be <= {}, got {}", number_text(max_length), number_text(length)));
            return false;
        }
        out = read;
        return true;
    }

    bool direction(const PresetJson& v, const std::string& path, Vec3& out) {
        Vec3 read = out;
        if (!vec3(v, path, read, symmetric(max_coordinate_m))) return false;
        if (read == Vec3(0.0)) {
            fail(path, "must not be the zero vector [0, 0, 0]");
            return false;
        }
        out = read;
        return true;
    }

    bool unsigned_integer(const PresetJson& v, const std::string& path, std::uint64_t& out, std::uint64_t max) {
        std::uint64_t x = 0;
        if (v.is_number_unsigned()) {
            x = v.get<std::uint64_t>();
        } else if (v.is_number_integer()) {
            fail(path, fmt::format("must be >= 0, got {}", v.get<std::int64_t>()));
            return false;
        } else if (v.is_number_float()) {
            const double d = v.get<double>();
            if (!std::isfinite(d)) {
                fail(path, "must be finite, but the number is too large for a double");
                return false;
            }
            if (d < 0) {
                fail(path, fmt::format("must be >= 0, got {}", number_text(d)));
                return false;
            }
            if (d != std::floor(d)) {
                fail(path, fmt::format("must be a whole number, got {}", number_text(d)));
                return false;
            }
            if (d >= 0x1.0p64 || static_cast<std::uint64_t>(d) > max) {
                fail(path, fmt::format("must be <= {}, got {}", max, number_text(d)));
                return false;
            }
            x = static_cast<std::uint64_t>(d);
        } else {
            fail(path, "expected a non-negative integer, got " + type_text(v));
            return false;
        }
        if (x > max) {
            fail(path, fmt::format("must be <= {}, got {}", max, x));
            return false;
        }
        out = x;
        return true;
    }

    bool string(const PresetJson& v, const std::string& path, std::string& out) {
        if (!v.is_string()) {
            fail(path, "expected a string, got " + type_text(v));
            return false;
        }
        out = v.get<std::string>();
        return true;
    }

    bool boolean(const PresetJson& v, const std::string& path, bool& out) {
        if (!v.is_boolean()) {
            fail(path, "expected true or false, got " + type_text(v));
            return false;
        }
        out = v.get<bool>();
        return true;
    }

    template <class E, std::size_t N>
    bool enumeration(const PresetJson& v, const std::string& path, E& out, const std::array<E, N>& values) {
        if (!v.is_string()) {
            fail(path, "expected a string (one of " + enum_names(values) + "), got " + type_text(v));
            return false;
        }
        const std::string& s = v.get_ref<const std::string&>();
        for (E e : values)
            if (s == to_string(e)) {
                out = e;
                return true;
            }
        fail(path, "unknown value " + quoted_for_message(s) + "; expected one of " + enum_names(values));
        return false;
    }

    // Checks `high >= low` for a range whose ends both read well.
    void ordered(bool both_ok, double low, double high, const std::string& high_path, const char* low_name) {
        if (both_ok && !(high >= low))
            fail(high_path, fmt::format("must be >= {} ({}), got {}", low_name, number_text(low), number_text(high)));
    }

    // ---------------------------------------------------------------- sections

    void room(const PresetJson& j, const std::string& path, Room& r) {
        bool center_ok = false, size_ok = false;
        const bool is_object = fields(j, path, {"center", "size"}, [&](const std::string& key, const PresetJson& v, const std::string& p) {
            if (key == "center") center_ok = vec3(v, p, r.center, symmetric(max_coordinate_m));
            else size_ok = vec3(v, p, r.size, positive(max_room_size_m));
        });
        require(j, path, {"center", "size"});
        room_ok_ = is_object && center_ok && size_ok;
    }

    void air(const PresetJson& j, const std::string& path, Air& a) {
        fields(j, path, {"density", "viscosity"}, [&](const std::string& key, const PresetJson& v, const std::string& p) {
            if (key == "density") number(v, p, a.density_kg_m3, positive(max_density_kg_m3));
            else number(v, p, a.viscosity_pa_s, positive(max_viscosity_pa_s));
        });
    }

    void wind(const PresetJson& j, const std::string& path, WindSettings& w) {
        fields(j, path,
               {"kind", "velocity", "amplitude", "period", "seed", "reference_height", "exponent", "center", "axis",
                "max_speed", "core_radius"},
               [&](const std::string& key, const PresetJson& v, const std::string& p) {
                   if (key == "kind") enumeration(v, p, w.kind, all_wind_kinds);
                   else if (key == "velocity") bounded_vec3(v, p, w.velocity, max_speed_mps);
                   else if (key == "amplitude") bounded_vec3(v, p, w.gust_amplitude, max_speed_mps);
                   else if (key == "period") number(v, p, w.gust_period_s, positive(max_period_s));
                   else if (key == "seed") unsigned_integer(v, p, w.gust_seed, std::numeric_limits<std::uint64_t>::max());
                   else if (key == "reference_height") number(v, p, w.reference_height_m, positive(max_room_size_m));
                   else if (key == "exponent") number(v, p, w.shear_exponent, closed(0.0, 1.0));
                   else if (key == "center") vec3(v, p, w.vortex_center, symmetric(max_coordinate_m));
                   else if (key == "axis") direction(v, p, w.vortex_axis);
                   else if (key == "max_speed") number(v, p, w.vortex_max_speed, non_negative(max_speed_mps));
                   else number(v, p, w.vortex_core_radius_m, positive(max_room_size_m));
               });
    }

    void world(const PresetJson& j, const std::string& path, World& w) {
        fields(j, path, {"gravity", "air", "wind"}, [&](const std::string& key, const PresetJson& v, const std::string& p) {
            if (key == "gravity") vec3(v, p, w.gravity, symmetric(max_gravity_mps2));
            else if (key == "air") air(v, p, w.air);
            else wind(v, p, w.wind);
        });
    }

    void drag(const PresetJson& j, const std::string& path, DragSettings& d) {
        fields(j, path, {"model", "cd", "b"}, [&](const std::string& key, const PresetJson& v, const std::string& p) {
            if (key == "model") enumeration(v, p, d.model, all_drag_models);
            else if (key == "cd") number(v, p, d.cd, positive(max_cd));
            else if (v.is_null()) d.linear_b.reset();  // Stokes: b = 6 pi mu R from the air
            else {
                double b = d.linear_b.value_or(0.0);
                if (number(v, p, b, non_negative(max_linear_b))) d.linear_b = b;
            }
        });
    }

    void contact(const PresetJson& j, const std::string& path, ContactSettings& c) {
        fields(j, path, {"restitution", "friction", "rest_speed"}, [&](const std::string& key, const PresetJson& v, const std::string& p) {
            if (key == "restitution") number(v, p, c.restitution, closed(0.0, 1.0));
            else if (key == "friction") number(v, p, c.friction, non_negative(max_friction));
            else number(v, p, c.rest_speed, non_negative(max_rest_speed_mps));
        });
    }

    void integrator(const PresetJson& j, const std::string& path, IntegratorSettings& s) {
        fields(j, path, {"method", "dt", "rtol", "atol", "adaptive"}, [&](const std::string& key, const PresetJson& v, const std::string& p) {
            if (key == "method") enumeration(v, p, s.method, all_methods);
            else if (key == "dt") number(v, p, s.dt, positive(max_dt_s));
            else if (key == "rtol") number(v, p, s.rtol, positive(max_tolerance));
            else if (key == "atol") number(v, p, s.atol, positive(max_tolerance));
            else boolean(v, p, s.adaptive);
        });
    }

    void particle(const PresetJson& j, const std::string& path, ParticleSpec& s) {
        bool position_ok = false, radius_ok = true;
        const bool is_object = fields(j, path, {"position", "velocity", "mass", "radius"},
                                      [&](const std::string& key, const PresetJson& v, const std::string& p) {
            if (key == "position") position_ok = vec3(v, p, s.position, any_finite());
            else if (key == "velocity") bounded_vec3(v, p, s.velocity, max_speed_mps);
            else if (key == "mass") number(v, p, s.mass, Bounds{min_mass_kg, false, max_mass_kg, false, false});
            else radius_ok = number(v, p, s.radius, positive(max_room_size_m));
        });
        require(j, path, {"position"});
        if (is_object && position_ok && radius_ok) pending_fits_.push_back({path, s.position, s.radius});
    }

    bool particles(const PresetJson& j, const std::string& path, std::vector<ParticleSpec>& out) {
        if (!j.is_array()) {
            fail(path, "expected an array of particle objects, got " + type_text(j));
            return false;
        }
        if (j.size() > max_preset_particles) {
            fail(path, fmt::format("lists {} particles; at most {} are allowed", j.size(), max_preset_particles));
            return false;
        }
        out.assign(j.size(), ParticleSpec{});
        for (std::size_t i = 0; i < j.size(); ++i) particle(j[i], json_path_index(path, i), out[i]);
        return true;
    }

    void emitter(const PresetJson& j, const std::string& path, Emitter& e) {
        bool region_min_ok = true, region_max_ok = true, speed_min_ok = true, speed_max_ok = true;
        bool mass_min_ok = true, mass_max_ok = true, radius_min_ok = true, radius_max_ok = true;
        const bool is_object = fields(j, path,
               {"count", "seed", "region_min", "region_max", "speed_min", "speed_max", "direction", "spread_deg",
                "mass_min", "mass_max", "radius_min", "radius_max"},
               [&](const std::string& key, const PresetJson& v, const std::string& p) {
                   if (key == "count") {
                       std::uint64_t count = 0;
                       emitter_count_ok_ = unsigned_integer(v, p, count, max_preset_particles);
                       if (emitter_count_ok_) e.count = static_cast<std::size_t>(count);
                   } else if (key == "seed") unsigned_integer(v, p, e.seed, std::numeric_limits<std::uint64_t>::max());
                   else if (key == "region_min") region_min_ok = vec3(v, p, e.region_min, symmetric(max_coordinate_m));
                   else if (key == "region_max") region_max_ok = vec3(v, p, e.region_max, symmetric(max_coordinate_m));
                   else if (key == "speed_min") speed_min_ok = number(v, p, e.speed_min, non_negative(max_speed_mps));
                   else if (key == "speed_max") speed_max_ok = number(v, p, e.speed_max, non_negative(max_speed_mps));
                   else if (key == "direction") direction(v, p, e.direction);
                   else if (key == "spread_deg") number(v, p, e.spread_deg, closed(0.0, 180.0));
                   else if (key == "mass_min") mass_min_ok = number(v, p, e.mass_min, Bounds{min_mass_kg, false, max_mass_kg, false, false});
                   else if (key == "mass_max") mass_max_ok = number(v, p, e.mass_max, Bounds{min_mass_kg, false, max_mass_kg, false, false});
                   else if (key == "radius_min") radius_min_ok = number(v, p, e.radius_min, positive(max_room_size_m));
                   else radius_max_ok = number(v, p, e.radius_max, positive(max_room_size_m));
               });
        require(j, path, {"count"});
        if (!is_object) return;
        for (int a = 0; a < 3; ++a)
            ordered(region_min_ok && region_max_ok, e.region_min[a], e.region_max[a],
                    json_path_index(json_path_key(path, "region_max"), static_cast<std::size_t>(a)),
                    a == 0 ? "region_min[0]" : a == 1 ? "region_min[1]" : "region_min[2]");
        ordered(speed_min_ok && speed_max_ok, e.speed_min, e.speed_max, json_path_key(path, "speed_max"), "speed_min");
        ordered(mass_min_ok && mass_max_ok, e.mass_min, e.mass_max, json_path_key(path, "mass_max"), "mass_min");
        ordered(radius_min_ok && radius_max_ok, e.radius_min, e.radius_max, json_path_key(path, "radius_max"), "radius_min");
        emitter_radius_ok_ = radius_min_ok && radius_max_ok;
    }

    void variant(const PresetJson& j, const std::string& path, const Scene& base, Variant& out) {
        fields(j, path, {"label", "drag", "wind", "air", "contact", "integrator"},
               [&](const std::string& key, const PresetJson& v, const std::string& p) {
                   // A variant's section starts from the scene's own, so it need only name what differs.
                   if (key == "label") {
                       if (string(v, p, out.label) && out.label.empty()) fail(p, "must not be empty");
                   } else if (key == "drag") {
                       out.drag = base.drag;
                       drag(v, p, *out.drag);
                   } else if (key == "wind") {
                       out.wind = base.world.wind;
                       wind(v, p, *out.wind);
                   } else if (key == "air") {
                       out.air = base.world.air;
                       air(v, p, *out.air);
                   } else if (key == "contact") {
                       out.contact = base.contact;
                       contact(v, p, *out.contact);
                   } else {
                       out.integrator = base.integrator;
                       integrator(v, p, *out.integrator);
                   }
               });
        require(j, path, {"label"});
    }

    void variants(const PresetJson& j, const std::string& path, Scene& scene) {
        if (!j.is_array()) {
            fail(path, "expected an array of variant objects, got " + type_text(j));
            return;
        }
        std::vector<Variant> read(j.size());
        for (std::size_t i = 0; i < j.size(); ++i) {
            const std::string p = json_path_index(path, i);
            variant(j[i], p, scene, read[i]);
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

    void version(const PresetJson& v, const std::string& path) {
        if (!v.is_number_integer()) {
            const bool overflowed = v.is_number_float() && !std::isfinite(v.get<double>());
            fail(path, "expected the integer 1, got " +
                           (overflowed ? "a number too large for a double" : v.is_number() ? v.dump() : type_text(v)));
            return;
        }
        if (!(v.is_number_unsigned() && v.get<std::uint64_t>() == 1))
            fail(path, "unsupported version " + v.dump() + "; this program reads version 1");
    }

    void format(const PresetJson& v, const std::string& path) {
        static const std::string expected = "particle-lab-preset";
        if (!v.is_string())
            fail(path, "expected the string \"" + expected + "\", got " + type_text(v));
        else if (v.get_ref<const std::string&>() != expected)
            fail(path, "must be \"" + expected + "\", got " + quoted_for_message(v.get<std::string>()) +
                           " (not a particle-lab preset?)");
    }

    // ---------------------------------------------------------------- cross-checks

    void check_fits(const Room& room) {
        const double smallest = std::min({room.size.x, room.size.y, room.size.z});
        const Vec3 lo = room.min_corner(), hi = room.max_corner();
        for (const PendingFit& f : pending_fits_) {
            if (!(f.radius < 0.5 * smallest)) {
                fail(json_path_key(f.path, "radius"),
                     fmt::format("must be < {} (half the room's smallest size), got {}", number_text(0.5 * smallest),
                                 number_text(f.radius)));
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
    }

    PresetErrorList& errors_;
    bool room_ok_ = false;
    bool emitter_radius_ok_ = false;
    bool emitter_count_ok_ = false;
    std::vector<PendingFit> pending_fits_;
};

void Reader::document(const PresetJson& doc, Scene& scene) {
    if (!doc.is_object()) {
        fail("", "expected a JSON object at the top level, got " + type_text(doc));
        return;
    }
    const PresetJson* variant_list = nullptr;
    bool particles_ok = false, particles_present = false, emitter_ok = false;
    fields(doc, "",
           {"format", "version", "name", "description", "room", "world", "drag", "contact", "integrator", "particles",
            "emitter", "variants"},
           [&](const std::string& key, const PresetJson& v, const std::string& p) {
               if (key == "format") format(v, p);
               else if (key == "version") version(v, p);
               else if (key == "name") string(v, p, scene.name);
               else if (key == "description") string(v, p, scene.description);
               else if (key == "room") room(v, p, scene.room);
               else if (key == "world") world(v, p, scene.world);
               else if (key == "drag") drag(v, p, scene.drag);
               else if (key == "contact") contact(v, p, scene.contact);
               else if (key == "integrator") integrator(v, p, scene.integrator);
               else if (key == "particles") {
                   particles_present = true;
                   particles_ok = particles(v, p, scene.particles);
               } else if (key == "emitter") {
                   scene.emitter.emplace();
                   emitter(v, p, *scene.emitter);
                   emitter_ok = emitter_count_ok_;
               } else variant_list = &v;  // read last: variant sections start from the scene's own
           });
    require(doc, "", {"format", "version", "room"});
    if (variant_list) variants(*variant_list, "variants", scene);

    const std::size_t emitted = scene.emitter ? scene.emitter->count : 0;
    const std::size_t total = scene.particles.size() + emitted;
    if (total == 0 && (particles_ok || !particles_present) && (emitter_ok || !scene.emitter))
        fail("particles", "the preset has no particles: give a non-empty \"particles\" list or an \"emitter\" with count >= 1");
    if (total > max_preset_particles)
        fail("emitter.count", fmt::format("the preset would create {} particles ({} listed + {} emitted); at most {} are allowed",
                                          total, scene.particles.size(), emitted, max_preset_particles));
    if (room_ok_) {
        check_fits(scene.room);
        const double smallest = std::min({scene.room.size.x, scene.room.size.y, scene.room.size.z});
        if (scene.emitter && emitter_radius_ok_ && !(scene.emitter->radius_max < 0.5 * smallest))
            fail("emitter.radius_max", fmt::format("must be < {} (half the room's smallest size), got {}",
                                                   number_text(0.5 * smallest), number_text(scene.emitter->radius_max)));
    }
}

}  // namespace

void read_preset_document(const PresetJson& doc, Scene& scene, PresetErrorList& errors) {
    Reader(errors).document(doc, scene);
}

}  // namespace pl
