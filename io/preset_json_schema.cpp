#include "io/preset_json_schema.hpp"

#include "io/preset_reader.hpp"
#include "io/preset_reference.hpp"
#include "physics/model/schema/scene_fields.hpp"

#include <cmath>

namespace pl {
namespace {

using schema::FieldKind;
using schema::NodeShape;
using schema::SchemaNode;

void add_bounds(PresetJson& j, const schema::Bounds& b) {
    if (std::isfinite(b.lo)) j[b.lo_open ? "exclusiveMinimum" : "minimum"] = b.lo;
    if (std::isfinite(b.hi)) j[b.hi_open ? "exclusiveMaximum" : "maximum"] = b.hi;
}

PresetJson number_schema(const schema::Bounds& b) {
    PresetJson j = {{"type", "number"}};
    add_bounds(j, b);
    return j;
}

PresetJson vec3_schema(const PresetJson& component) {
    return {{"type", "array"}, {"items", component}, {"minItems", 3}, {"maxItems", 3}};
}

PresetJson default_json(const schema::DefaultValue& v) {
    return std::visit(
        [](const auto& x) -> PresetJson {
            using T = std::remove_cvref_t<decltype(x)>;
            if constexpr (std::is_same_v<T, std::monostate>) return nullptr;
            else if constexpr (std::is_same_v<T, Vec3>) return PresetJson::array({x.x, x.y, x.z});
            else if constexpr (std::is_same_v<T, std::optional<double>>) return x ? PresetJson(*x) : PresetJson(nullptr);
            else return x;
        },
        v);
}

PresetJson kind_schema(const schema::FieldInfo& f) {
    switch (f.kind) {
        case FieldKind::number: return number_schema(f.bounds);
        case FieldKind::vec3: return vec3_schema(number_schema(f.bounds));
        // A JSON Schema cannot bound a length; each component's bound is the necessary part of it.
        case FieldKind::bounded_vec3: return vec3_schema(number_schema(schema::symmetric(f.bounds.hi)));
        case FieldKind::direction: {
            PresetJson j = vec3_schema(number_schema(f.bounds));
            j["not"] = {{"const", PresetJson::array({0, 0, 0})}};
            return j;
        }
        case FieldKind::unsigned_integer: return {{"type", "integer"}, {"minimum", 0}, {"maximum", f.max_integer}};
        case FieldKind::boolean: return {{"type", "boolean"}};
        case FieldKind::string: {
            PresetJson j = {{"type", "string"}};
            if (f.non_empty) j["minLength"] = 1;
            return j;
        }
        case FieldKind::enumeration: {
            PresetJson names = PresetJson::array();
            for (int i = 0; i < f.names.count; ++i) names.push_back(f.names.name(i));
            return {{"enum", names}};
        }
        case FieldKind::optional_number: {
            PresetJson j = {{"type", PresetJson::array({"number", "null"})}};
            add_bounds(j, f.bounds);
            return j;
        }
        case FieldKind::format_tag: return {{"const", schema::preset_format_name}};
        case FieldKind::version_tag: return {{"const", schema::preset_format_version}};
    }
    return PresetJson::object();
}

std::string description(const SchemaNode& n) {
    // Built by appending: GCC 12 gives a false -Wrestrict for "[" + std::string&&.
    std::string text;
    if (n.shape == NodeShape::field && n.field.unit[0]) text.append("[").append(n.field.unit).append("] ");
    text += n.help;
    if (n.selector) text += " (used when " + std::string(n.selector->key) + " is " + schema::shown_for_text(n) + ")";
    return text;
}

PresetJson field_schema(const SchemaNode& n) {
    PresetJson j = {{"title", n.field.label}, {"description", description(n)}};
    j.update(kind_schema(n.field));
    if (!n.required && n.shape == NodeShape::field) j["default"] = default_json(n.default_value);
    return j;
}

// An object section, placed in $defs under its section name (a variant's drag is the scene's).
PresetJson object_schema(const SchemaNode& n, PresetJson& defs);

PresetJson child_schema(const SchemaNode& c, PresetJson& defs) {
    if (c.shape == NodeShape::field) return field_schema(c);
    if (!defs.contains(c.section)) defs[c.section] = object_schema(c, defs);
    const PresetJson ref = {{"$ref", "#/$defs/" + c.section}};
    if (c.shape != NodeShape::array) return {{"description", c.help}, {"$ref", ref["$ref"]}};
    return {{"description", c.help}, {"type", "array"}, {"items", ref}, {"maxItems", schema::max_particles}};
}

PresetJson object_schema(const SchemaNode& n, PresetJson& defs) {
    PresetJson properties = PresetJson::object();
    PresetJson required = PresetJson::array();
    for (const SchemaNode& c : n.children) {
        properties[c.key] = child_schema(c, defs);
        if (c.required) required.push_back(c.key);
    }
    PresetJson j = {{"type", "object"}, {"properties", properties}, {"additionalProperties", false}};
    if (!required.empty()) j["required"] = required;
    return j;
}

}  // namespace

std::string preset_json_schema() {
    const SchemaNode& tree = schema::preset_schema_tree();
    PresetJson defs = PresetJson::object();
    PresetJson doc = {{"$schema", "https://json-schema.org/draft/2020-12/schema"},
                      {"title", "particle-lab preset"},
                      {"description", std::string(schema::preset_format_name) + ", version 1: " + tree.help +
                                          " Generated from the preset rows; see `particle-lab validate --format`."}};
    doc.update(object_schema(tree, defs));
    // The one cross-field rule a schema can state: at least one particle, listed or emitted.
    doc["anyOf"] = PresetJson::array(
        {{{"required", {"particles"}}, {"properties", {{"particles", {{"minItems", 1}}}}}},
         {{"required", {"emitter"}}, {"properties", {{"emitter", {{"properties", {{"count", {{"minimum", 1}}}}}}}}}}});
    doc["$defs"] = defs;
    return doc.dump(2) + "\n";
}

}  // namespace pl
