// The preset format as a tree of plain values, built from the section rows: for the consumers
// that walk the format without touching a Scene (the format reference, the JSON Schema, the fuzz
// dictionary). Defaults are read from the structs' default member initialisers.
#pragma once

#include "physics/model/field_schema.hpp"

#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace pl::schema {

using DefaultValue = std::variant<std::monostate, double, Vec3, std::uint64_t, bool, std::string, std::optional<double>>;

enum class NodeShape { field, object, optional_object, array };

struct SchemaNode {
    NodeShape shape = NodeShape::object;
    std::string key;      // "" for the document itself
    std::string section;  // object shapes: the section's name (SectionSchema<T>::name), e.g. "drag"
    std::string help;
    bool required = false;
    std::string item_name;  // array: "particle"
    FieldInfo field;        // field shape
    DefaultValue default_value;
    // field shape, shown_for != always: the section's enumeration row that selects it.
    const FieldInfo* selector = nullptr;
    std::vector<SchemaNode> children;  // object shapes: the rows, then the nested sections
};

// The whole preset document (shape object, key "").
const SchemaNode& preset_schema_tree();

// The enumeration values (names) a field is shown for, "gust" or "constant, gust, shear".
std::string shown_for_text(const SchemaNode& field);

}  // namespace pl::schema
