#include "physics/model/schema/schema_tree.hpp"

#include "physics/model/schema/scene_fields.hpp"

namespace pl::schema {
namespace {

// GCC 12 inlines every case for every section and then flags the (never taken) case that would
// copy a Vec3 member out of a section without one, such as Air, as out of bounds.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Warray-bounds"
template <class S>
DefaultValue default_of(const Field<S>& f, const S& s) {
    switch (f.info.kind) {
        case FieldKind::number: return s.*std::get<double S::*>(f.member);
        case FieldKind::vec3:
        case FieldKind::bounded_vec3:
        case FieldKind::direction: return s.*std::get<Vec3 S::*>(f.member);
        case FieldKind::unsigned_integer: return s.*std::get<std::uint64_t S::*>(f.member);
        case FieldKind::boolean: return s.*std::get<bool S::*>(f.member);
        case FieldKind::string: return s.*std::get<std::string S::*>(f.member);
        case FieldKind::optional_number: return s.*std::get<std::optional<double> S::*>(f.member);
        case FieldKind::enumeration:
            return std::string(f.info.names.name(std::get<EnumAccess<S>>(f.member).get(s)));
        case FieldKind::format_tag:
        case FieldKind::version_tag: return std::monostate{};
    }
    return std::monostate{};
}
#pragma GCC diagnostic pop

template <class T>
struct ShapeOf {
    using Section = T;
    static constexpr NodeShape shape = NodeShape::object;
};
template <class T>
struct ShapeOf<std::optional<T>> {
    using Section = T;
    static constexpr NodeShape shape = NodeShape::optional_object;
};
template <class T>
struct ShapeOf<std::vector<T>> {
    using Section = T;
    static constexpr NodeShape shape = NodeShape::array;
};

template <class S>
SchemaNode section_node(const ChildInfo& info, NodeShape shape) {
    SchemaNode n;
    n.shape = shape;
    n.key = info.key;
    n.section = SectionSchema<S>::name;
    n.help = info.help;
    n.required = info.required;
    n.item_name = info.item_name;
    const S defaults{};
    const auto rows = SectionSchema<S>::rows;
    for (const Field<S>& f : rows) {
        SchemaNode leaf;
        leaf.shape = NodeShape::field;
        leaf.key = f.info.key;
        leaf.help = f.info.help;
        leaf.required = f.info.required;
        leaf.field = f.info;
        leaf.default_value = default_of(f, defaults);
        if (f.info.shown_for != always) leaf.selector = &rows.front().info;
        n.children.push_back(std::move(leaf));
    }
    SectionSchema<S>::children([&](const ChildInfo& c, auto member, auto&&...) {
        using M = std::remove_cvref_t<decltype(std::declval<S&>().*member)>;
        n.children.push_back(section_node<typename ShapeOf<M>::Section>(c, ShapeOf<M>::shape));
    });
    return n;
}

}  // namespace

const SchemaNode& preset_schema_tree() {
    static const SchemaNode tree = section_node<Scene>(ChildInfo{"", "A particle-lab preset.", true}, NodeShape::object);
    return tree;
}

std::string shown_for_text(const SchemaNode& field) {
    std::string out;
    if (!field.selector) return out;
    for (int i = 0; i < field.selector->names.count; ++i)
        if (field.field.shown_for >> i & 1u) out += (out.empty() ? "" : ", ") + std::string(field.selector->names.name(i));
    return out;
}

}  // namespace pl::schema
