#include "io/preset_writer.hpp"

#include "physics/model/schema/scene_fields.hpp"

namespace pl {
namespace {

using schema::Field;
using schema::SectionSchema;

PresetJson vec_json(const Vec3& v) { return PresetJson::array({v.x, v.y, v.z}); }

template <class S>
PresetJson field_json(const Field<S>& f, const S& s) {
    using K = schema::FieldKind;
    switch (f.info.kind) {
        case K::number: return s.*std::get<double S::*>(f.member);
        case K::vec3:
        case K::bounded_vec3:
        case K::direction: return vec_json(s.*std::get<Vec3 S::*>(f.member));
        case K::unsigned_integer: return s.*std::get<std::uint64_t S::*>(f.member);
        case K::boolean: return s.*std::get<bool S::*>(f.member);
        case K::string: return s.*std::get<std::string S::*>(f.member);
        case K::enumeration: {
            const auto& access = std::get<schema::EnumAccess<S>>(f.member);
            return f.info.names.name(access.get(s));
        }
        case K::optional_number: {
            // Always written (null = absent) so that a variant's section never inherits the
            // scene's value on reload (e.g. drag.b: null = Stokes from the air).
            const std::optional<double>& x = s.*std::get<std::optional<double> S::*>(f.member);
            return x ? PresetJson(*x) : PresetJson(nullptr);
        }
        case K::format_tag: return schema::preset_format_name;
        case K::version_tag: return schema::preset_format_version;
    }
    return nullptr;
}

template <class S>
PresetJson section_json(const S& s);

template <class T>
void child_json(PresetJson& j, const char* key, const T& v) {
    j[key] = section_json(v);
}
template <class T>
void child_json(PresetJson& j, const char* key, const std::optional<T>& v) {
    if (v) j[key] = section_json(*v);  // an absent section (no emitter, a variant's own) is left out
}
template <class T>
void child_json(PresetJson& j, const char* key, const std::vector<T>& v) {
    PresetJson& list = j[key] = PresetJson::array();
    for (const T& item : v) list.push_back(section_json(item));
}

template <class S>
PresetJson section_json(const S& s) {
    PresetJson j = PresetJson::object();
    for (const Field<S>& f : SectionSchema<S>::rows) j[f.info.key] = field_json(f, s);
    SectionSchema<S>::children([&](const schema::ChildInfo& c, auto member, auto&&...) { child_json(j, c.key, s.*member); });
    return j;
}

}  // namespace

PresetJson preset_document(const Scene& scene) { return section_json(scene); }

}  // namespace pl
