// The preset format's single definition: one row per field, plain data (no JSON, no ImGui).
// The reader and writer (io/), the format reference (`particle-lab validate --format`), the JSON
// Schema (`particle-lab schema`), the GUI editor (ui/scene_editor.cpp), the fuzz dictionary and
// the tests' scene comparison all iterate these rows (as Jolt's JPH_ADD_ATTRIBUTE lists and
// MuJoCo simulate's mjuiDef tables do), so a field is added, bounded or documented once.
//
// Each section's rows live in physics/model/schema/<section>_fields.hpp as a specialisation of
// SectionSchema<S>: `rows` (the scalar fields) and `children(visit)` (the nested sections, in the
// order the writer writes them and the reader lists them). The default of every field is the
// struct's own default member initialiser, read from S{}.
#pragma once

#include "physics/model/scene.hpp"

#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>

namespace pl::schema {

enum class FieldKind {
    number,            // a finite double within `bounds`
    vec3,              // [x, y, z], each component within `bounds`
    bounded_vec3,      // [x, y, z] of length <= bounds.hi (velocities, amplitudes)
    direction,         // [x, y, z] within `bounds`, not the zero vector
    unsigned_integer,  // a whole number in [0, max_integer] (a float with no fraction is accepted)
    boolean,
    string,
    enumeration,       // one of the names in `names`
    optional_number,   // a number within `bounds`, or null / omitted for "absent"
    format_tag,        // the constant "particle-lab-preset"
    version_tag,       // the constant integer 1
};

constexpr double inf = std::numeric_limits<double>::infinity();

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
// [lo, hi] with the one-sided messages ("must be >= lo", "must be <= hi").
constexpr Bounds at_least(double lo, double hi) { return {lo, false, hi, false, false}; }
// bounded_vec3: the largest length.
constexpr Bounds max_length(double limit) { return {-inf, false, limit, false, false}; }

// The names of an enumeration whose values are 0 .. count-1 (name(i) is its to_string).
struct EnumNames {
    int count = 0;
    const char* (*name)(int) = nullptr;
};

template <class S>
struct EnumAccess {
    int (*get)(const S&) = nullptr;
    void (*set)(S&, int) = nullptr;
};

static_assert(std::is_same_v<std::size_t, std::uint64_t>, "Emitter::count is read as a uint64");

template <class S>
using Member = std::variant<std::monostate, double S::*, Vec3 S::*, std::uint64_t S::*, bool S::*, std::string S::*,
                            std::optional<double> S::*, EnumAccess<S>>;

constexpr std::uint32_t always = ~std::uint32_t{0};

// The descriptive part of a row: everything but where the value lives.
struct FieldInfo {
    const char* key = "";
    FieldKind kind = FieldKind::number;
    const char* unit = "";  // SI, ASCII ("m/s^2"); "" for dimensionless
    Bounds bounds;
    std::uint64_t max_integer = 0;  // unsigned_integer only
    EnumNames names;                // enumeration only
    const char* label = "";         // short name in the GUI
    const char* help = "";          // one sentence: the format reference, the schema, the GUI tooltip
    bool required = false;
    bool non_empty = false;  // string only: "" is refused
    // Bit i set: the field matters when the section's enumeration (its first row) has value i,
    // e.g. wind.period only for gusts. The GUI shows only those; the others are still read and written.
    std::uint32_t shown_for = always;
};

template <class S>
struct Field {
    FieldInfo info;
    Member<S> member;

    constexpr Field when(std::uint32_t mask) const {
        Field f = *this;
        f.info.shown_for = mask;
        return f;
    }
    constexpr Field required() const {
        Field f = *this;
        f.info.required = true;
        return f;
    }
    constexpr Field non_empty() const {
        Field f = *this;
        f.info.non_empty = true;
        return f;
    }
};

template <auto E>
constexpr std::uint32_t bit() { return std::uint32_t{1} << static_cast<int>(E); }

// ---------------------------------------------------------------- row builders

template <class S>
constexpr Field<S> number(const char* key, double S::*m, const char* unit, Bounds b, const char* label, const char* help) {
    return {{key, FieldKind::number, unit, b, 0, {}, label, help}, m};
}

template <class S>
constexpr Field<S> vec3(const char* key, Vec3 S::*m, const char* unit, Bounds b, const char* label, const char* help) {
    return {{key, FieldKind::vec3, unit, b, 0, {}, label, help}, m};
}

template <class S>
constexpr Field<S> bounded_vec3(const char* key, Vec3 S::*m, const char* unit, double max_len, const char* label,
                                const char* help) {
    return {{key, FieldKind::bounded_vec3, unit, max_length(max_len), 0, {}, label, help}, m};
}

template <class S>
constexpr Field<S> direction(const char* key, Vec3 S::*m, double limit, const char* label, const char* help) {
    return {{key, FieldKind::direction, "", symmetric(limit), 0, {}, label, help}, m};
}

template <class S>
constexpr Field<S> unsigned_integer(const char* key, std::uint64_t S::*m, std::uint64_t max, const char* label,
                                    const char* help) {
    return {{key, FieldKind::unsigned_integer, "", {}, max, {}, label, help}, m};
}

template <class S>
constexpr Field<S> boolean(const char* key, bool S::*m, const char* label, const char* help) {
    return {{key, FieldKind::boolean, "", {}, 0, {}, label, help}, m};
}

template <class S>
constexpr Field<S> string(const char* key, std::string S::*m, const char* label, const char* help) {
    return {{key, FieldKind::string, "", {}, 0, {}, label, help}, m};
}

template <class S>
constexpr Field<S> optional_number(const char* key, std::optional<double> S::*m, const char* unit, Bounds b,
                                   const char* label, const char* help) {
    return {{key, FieldKind::optional_number, unit, b, 0, {}, label, help}, m};
}

// An enumeration member `M` of S with `count` values 0 .. count-1, named by pl::to_string.
template <class S, auto M>
constexpr Field<S> enumeration(const char* key, int count, const char* label, const char* help) {
    using E = std::remove_cvref_t<decltype(std::declval<S&>().*M)>;
    EnumAccess<S> access{[](const S& s) { return static_cast<int>(s.*M); },
                         [](S& s, int v) { s.*M = static_cast<E>(v); }};
    EnumNames names{count, [](int i) { return to_string(static_cast<E>(i)); }};
    return {{key, FieldKind::enumeration, "", {}, 0, names, label, help}, access};
}

template <class S>
constexpr Field<S> tag(const char* key, FieldKind kind, const char* help) {
    return {{key, kind, "", {}, 0, {}, key, help, true, false}, std::monostate{}};
}

// ---------------------------------------------------------------- nested sections

enum class ChildShape {
    object,           // a section always present in the struct
    optional_object,  // std::optional<T>: written only when set
    array,            // std::vector<T>
};

struct ChildInfo {
    const char* key = "";
    const char* help = "";
    bool required = false;
    const char* item_name = "";  // array: "particle" in "expected an array of particle objects"
};

// Specialised per section in physics/model/schema/*_fields.hpp:
//   static constexpr const char* name;            // e.g. "drag"
//   static constexpr std::span<const Field<S>> rows;
//   template <class V> static void children(V&& visit);   // visit(ChildInfo, &S::member) per child
template <class S>
struct SectionSchema;

// Leaf sections have no children.
struct NoChildren {
    template <class V>
    static void children(V&&) {}
};

// The index of a row by key, or -1.
template <class S>
constexpr int row_index(const char* key) {
    const auto& rows = SectionSchema<S>::rows;
    for (std::size_t i = 0; i < rows.size(); ++i)
        if (std::string_view(rows[i].info.key) == key) return static_cast<int>(i);
    return -1;
}

}  // namespace pl::schema
