#include "io/preset_reference.hpp"

#include "physics/model/start_packing.hpp"
#include "physics/model/schema/scene_fields.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace pl {
namespace {

using schema::FieldKind;
using schema::NodeShape;
using schema::SchemaNode;

std::string short_number(double x) { return fmt::format("{:.6g}", x); }

std::string enum_list(const schema::EnumNames& names, const char* separator) {
    std::string out;
    for (int i = 0; i < names.count; ++i) out += (i ? separator : "") + std::string(names.name(i));
    return out;
}

// What a field accepts, e.g. "number > 0, <= 1e+06" or "one of none | linear".
std::string accepts_text(const schema::FieldInfo& f) {
    switch (f.kind) {
        case FieldKind::number: return "number " + bounds_text(f.bounds);
        case FieldKind::vec3: return "[x, y, z], each " + bounds_text(f.bounds);
        case FieldKind::bounded_vec3: return "[x, y, z] of length <= " + short_number(f.bounds.hi);
        case FieldKind::direction: return "[x, y, z], each " + bounds_text(f.bounds) + ", not [0, 0, 0]";
        case FieldKind::unsigned_integer: return fmt::format("integer in [0, {}]", f.max_integer);
        case FieldKind::boolean: return "true or false";
        case FieldKind::string: return f.non_empty ? "string, not empty" : "string";
        case FieldKind::enumeration: return "one of " + enum_list(f.names, " | ");
        case FieldKind::optional_number: return "number " + bounds_text(f.bounds) + ", or null";
        case FieldKind::format_tag: return fmt::format("\"{}\"", schema::preset_format_name);
        case FieldKind::version_tag: return fmt::format("{}", schema::preset_format_version);
    }
    return "";
}

std::string field_line(const SchemaNode& n) {
    std::string text = accepts_text(n.field);
    if (n.required) text += "; required";
    else text += "; default " + default_text(n.default_value);
    if (n.selector) text += fmt::format("; used when {} is {}", n.selector->key, schema::shown_for_text(n));
    return text;
}

std::string section_line(const SchemaNode& n) {
    std::string text = n.shape == NodeShape::array ? "array of " + n.item_name + " objects" : "object";
    if (n.required) text += "; required";
    if (n.shape == NodeShape::optional_object) text += "; optional";
    return text;
}

void append_entry(std::string& out, const std::string& name, const std::string& what, const std::string& help) {
    constexpr std::size_t column = 34;
    const std::string padded = name.size() + 2 < column ? name + std::string(column - 2 - name.size(), ' ') : name + "  ";
    out += "  " + padded + what + "\n";
    // The help, word-wrapped to 100 columns under the description.
    constexpr std::size_t width = 100;
    std::string line;
    for (std::size_t at = 0; at < help.size();) {
        std::size_t end = help.find(' ', at);
        if (end == std::string::npos) end = help.size();
        const std::string word = help.substr(at, end - at);
        if (!line.empty() && column + line.size() + 1 + word.size() > width) {
            out += std::string(column, ' ') + line + "\n";
            line.clear();
        }
        line += (line.empty() ? "" : " ") + word;
        at = end + 1;
    }
    if (!line.empty()) out += std::string(column, ' ') + line + "\n";
}

void append_node(std::string& out, const SchemaNode& n, const std::string& path, bool variant) {
    for (const SchemaNode& c : n.children) {
        std::string name = path.empty() ? c.key : path + "." + c.key;
        if (c.shape == NodeShape::field) {
            const std::string unit = c.field.unit[0] ? fmt::format(" [{}]", c.field.unit) : "";
            append_entry(out, name + unit, field_line(c), c.help);
        } else if (variant) {
            // A variant's sections have the keys of the scene's; listing them again adds nothing.
            append_entry(out, name, "object; the keys of " + c.section, c.help);
        } else {
            append_entry(out, name, section_line(c), c.help);
            if (c.shape == NodeShape::array) name += "[]";
            append_node(out, c, name, c.section == "variant");
        }
    }
}

}  // namespace

std::string default_text(const schema::DefaultValue& v) {
    return std::visit(
        [](const auto& x) -> std::string {
            using T = std::remove_cvref_t<decltype(x)>;
            if constexpr (std::is_same_v<T, std::monostate>) return "";
            else if constexpr (std::is_same_v<T, double>) return short_number(x);
            else if constexpr (std::is_same_v<T, Vec3>)
                return fmt::format("[{}, {}, {}]", short_number(x.x), short_number(x.y), short_number(x.z));
            else if constexpr (std::is_same_v<T, bool>) return x ? "true" : "false";
            else if constexpr (std::is_same_v<T, std::string>) return fmt::format("\"{}\"", x);
            else if constexpr (std::is_same_v<T, std::optional<double>>) return x ? short_number(*x) : "null";
            else return fmt::format("{}", x);
        },
        v);
}

std::string bounds_text(const schema::Bounds& b) {
    if (b.interval)
        return fmt::format("in {}{}, {}{}", b.lo_open ? "(" : "[", short_number(b.lo), short_number(b.hi), b.hi_open ? ")" : "]");
    std::string out;
    if (std::isfinite(b.lo)) out += fmt::format("{} {}", b.lo_open ? ">" : ">=", short_number(b.lo));
    if (std::isfinite(b.hi)) out += fmt::format("{}{} {}", out.empty() ? "" : ", ", b.hi_open ? "<" : "<=", short_number(b.hi));
    return out.empty() ? "finite" : out;
}

std::string preset_format_reference() {
    std::string out = fmt::format("Format \"{}\", version {}. Keys (SI units; [x, y, z] arrays; y is up):\n\n",
                                  schema::preset_format_name, schema::preset_format_version);
    append_node(out, schema::preset_schema_tree(), "", false);
    out += fmt::format(
        "\n"
        "Omitted sections and fields take the defaults shown. Rules that span fields: at least one\n"
        "particle (from `particles`, `emitter`, or both; at most {0} in all); every particle fits\n"
        "inside the room (radius < half its smallest size, centre a radius away from every wall);\n"
        "emitter region_min <= region_max per axis, speed_min <= speed_max, mass_min <= mass_max,\n"
        "radius_min <= radius_max; with collisions on in some run (the scene's, where a variant does\n"
        "not turn them off, or a variant's), the emitter's balls\n"
        "have a volume fraction of at most {1} in the space they start in (the region of centres inside\n"
        "the room, grown by a radius), and the listed balls overlap in at most {2} pairs per ball;\n"
        "variant labels unique; an expectation's particle and variant exist; a variant's section\n"
        "starts from the scene's own, so a variant need only name what differs. Unknown keys,\n"
        "duplicate keys, wrong types,\n"
        "non-finite numbers (1e400 overflows to infinity) and out-of-range values are errors; every\n"
        "one is reported with its JSON path. Saved files list every field, defaults included.\n",
        schema::max_particles, short_number(max_start_volume_fraction), short_number(max_start_overlaps_per_ball));
    return out;
}

}  // namespace pl

namespace pl {
namespace {

void collect_tokens(const schema::SchemaNode& n, std::vector<std::string>& tokens) {
    const auto add = [&](const std::string& t) {
        if (std::find(tokens.begin(), tokens.end(), t) == tokens.end()) tokens.push_back(t);
    };
    for (const schema::SchemaNode& c : n.children) {
        add(c.key);
        if (c.field.kind == schema::FieldKind::format_tag) add(schema::preset_format_name);
        if (c.shape == schema::NodeShape::field && c.field.kind == schema::FieldKind::enumeration)
            for (int i = 0; i < c.field.names.count; ++i) add(c.field.names.name(i));
        collect_tokens(c, tokens);
    }
}

}  // namespace

std::string preset_fuzz_dictionary() {
    std::vector<std::string> tokens;
    collect_tokens(schema::preset_schema_tree(), tokens);
    std::string out;
    // Keys and names are identifiers: no character needs escaping beyond the quotes.
    for (const std::string& t : tokens) out += "\"\\\"" + t + "\\\"\"\n";
    return out;
}

}  // namespace pl
