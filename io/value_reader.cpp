#include "io/value_reader.hpp"

#include "physics/model/schema/scene_fields.hpp"

#include <fmt/format.h>

#include <cmath>

namespace pl {

std::string number_text(double x) { return fmt::format("{}", x); }
std::string vec_text(const Vec3& v) { return fmt::format("[{}, {}, {}]", v.x, v.y, v.z); }

std::string type_text(const PresetJson& v) {
    if (v.is_number()) return "number";
    if (v.is_boolean()) return "boolean";
    return v.type_name();  // string, array, object, null
}

std::string enum_names_text(const schema::EnumNames& names) {
    std::string out;
    for (int i = 0; i < names.count; ++i) {
        if (!out.empty()) out += ", ";
        out += names.name(i);
    }
    return out;
}

bool ValueReader::number(const PresetJson& v, const std::string& path, double& out, const schema::Bounds& b) {
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
        fail(path, fmt::format("must be in {}{}, {}{}, got {}", b.lo_open ? "(" : "[", number_text(b.lo), number_text(b.hi),
                               b.hi_open ? ")" : "]", number_text(x)));
    else if (below)
        fail(path, fmt::format("must be {} {}, got {}", b.lo_open ? ">" : ">=", number_text(b.lo), number_text(x)));
    else
        fail(path, fmt::format("must be {} {}, got {}", b.hi_open ? "<" : "<=", number_text(b.hi), number_text(x)));
    return false;
}

bool ValueReader::vec3(const PresetJson& v, const std::string& path, Vec3& out, const schema::Bounds& b) {
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

bool ValueReader::bounded_vec3(const PresetJson& v, const std::string& path, Vec3& out, double max_length) {
    Vec3 read = out;
    if (!vec3(v, path, read, schema::any_finite())) return false;
    const double length = glm::length(read);
    if (!(length <= max_length)) {
        fail(path, fmt::format("magnitude must be <= {}, got {}", number_text(max_length), number_text(length)));
        return false;
    }
    out = read;
    return true;
}

bool ValueReader::direction(const PresetJson& v, const std::string& path, Vec3& out, const schema::Bounds& b) {
    Vec3 read = out;
    if (!vec3(v, path, read, b)) return false;
    if (read == Vec3(0.0)) {
        fail(path, "must not be the zero vector [0, 0, 0]");
        return false;
    }
    out = read;
    return true;
}

bool ValueReader::unsigned_integer(const PresetJson& v, const std::string& path, std::uint64_t& out, std::uint64_t max) {
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

bool ValueReader::string(const PresetJson& v, const std::string& path, std::string& out, bool non_empty) {
    if (!v.is_string()) {
        fail(path, "expected a string, got " + type_text(v));
        return false;
    }
    out = v.get<std::string>();
    if (non_empty && out.empty()) {
        fail(path, "must not be empty");
        return false;
    }
    return true;
}

bool ValueReader::boolean(const PresetJson& v, const std::string& path, bool& out) {
    if (!v.is_boolean()) {
        fail(path, "expected true or false, got " + type_text(v));
        return false;
    }
    out = v.get<bool>();
    return true;
}

bool ValueReader::enumeration(const PresetJson& v, const std::string& path, int& out, const schema::EnumNames& names) {
    if (!v.is_string()) {
        fail(path, "expected a string (one of " + enum_names_text(names) + "), got " + type_text(v));
        return false;
    }
    const std::string& s = v.get_ref<const std::string&>();
    for (int i = 0; i < names.count; ++i)
        if (s == names.name(i)) {
            out = i;
            return true;
        }
    fail(path, "unknown value " + quoted_for_message(s) + "; expected one of " + enum_names_text(names));
    return false;
}

bool ValueReader::optional_number(const PresetJson& v, const std::string& path, std::optional<double>& out,
                                  const schema::Bounds& b) {
    if (v.is_null()) {
        out.reset();
        return true;
    }
    double x = out.value_or(0.0);
    if (!number(v, path, x, b)) return false;
    out = x;
    return true;
}

bool ValueReader::version_tag(const PresetJson& v, const std::string& path) {
    if (!v.is_number_integer()) {
        const bool overflowed = v.is_number_float() && !std::isfinite(v.get<double>());
        fail(path, "expected the integer 1, got " +
                       (overflowed ? "a number too large for a double" : v.is_number() ? v.dump() : type_text(v)));
        return false;
    }
    if (!(v.is_number_unsigned() && v.get<std::uint64_t>() == schema::preset_format_version)) {
        fail(path, "unsupported version " + v.dump() + "; this program reads version 1");
        return false;
    }
    return true;
}

bool ValueReader::format_tag(const PresetJson& v, const std::string& path) {
    static const std::string expected = schema::preset_format_name;
    if (!v.is_string()) {
        fail(path, "expected the string \"" + expected + "\", got " + type_text(v));
        return false;
    }
    if (v.get_ref<const std::string&>() != expected) {
        fail(path, "must be \"" + expected + "\", got " + quoted_for_message(v.get<std::string>()) +
                       " (not a particle-lab preset?)");
        return false;
    }
    return true;
}

}  // namespace pl
