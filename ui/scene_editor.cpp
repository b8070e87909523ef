#include "ui/scene_editor.hpp"

#include "io/preset_reference.hpp"
#include "physics/model/drag.hpp"
#include "physics/model/schema/scene_fields.hpp"
#include "ui/scene_validation.hpp"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <cmath>
#include <string>

namespace pl::ui {

SceneEditor::SceneEditor(LabSession& s) : s_(s), panels_(panels_of(s)) {
    // Refusals belong to the scene they were made against.
    if (panels_.edits_experiment != s.experiment.get()) {
        panels_.fields.refused.clear();
        panels_.edits_experiment = s.experiment.get();
    }
}

bool SceneEditor::commit(const std::function<void(Scene&)>& change, bool from_field) {
    Scene edited = s_.scene;
    change(edited);
    const std::string errors = scene_errors(edited);
    if (from_field) panels_.fields.resolve(errors);
    if (!errors.empty()) {
        if (!from_field) s_.error_popup = "This change was not applied:\n" + errors;
        return false;
    }
    if (const std::string refused = s_.apply_scene(edited); !refused.empty()) {
        s_.error_popup = "This change was not applied: " + refused;
        return false;
    }
    s_.dirty = true;
    panels_.edits_experiment = s_.experiment.get();  // keep the field's own refusal state
    return true;
}

void SceneEditor::number(const char* label, double value, const std::function<void(Scene&, double)>& set,
                         const char* format, const char* help) {
    const std::optional<double> v = input_number(panels_.fields, label, value, format, help);
    if (v) commit([&](Scene& sc) { set(sc, *v); }, true);
}

void SceneEditor::vec3(const char* label, const Vec3& value, const std::function<void(Scene&, const Vec3&)>& set,
                       const char* format, const char* help) {
    const std::optional<Vec3> v = input_vec3(panels_.fields, label, value, format, help);
    if (v) commit([&](Scene& sc) { set(sc, *v); }, true);
}

void SceneEditor::integer(const char* label, std::uint64_t value, const std::function<void(Scene&, std::uint64_t)>& set,
                          const char* help) {
    const std::optional<double> v = input_number(panels_.fields, label, static_cast<double>(value), "%.0f", help);
    if (!v) return;
    // Only what a double cannot carry into a uint64 is refused here; the field's bound is the
    // row's, checked with every other rule by scene_errors (the preset reader).
    if (!(*v >= 0.0 && *v < 0x1.0p64 && std::floor(*v) == *v)) {
        panels_.fields.resolve(std::string(label) + ": must be a whole number >= 0 (and below 2^64), got " +
                               std::to_string(*v));
        return;
    }
    const auto n = static_cast<std::uint64_t>(*v);
    commit([&](Scene& sc) { set(sc, n); }, true);
}

void SceneEditor::text(const char* label, const std::string& value,
                       const std::function<void(Scene&, const std::string&)>& set) {
    const ImGuiID id = ImGui::GetID(label);
    if (panels_.text_editing != id) panels_.text_buffers[id] = value;
    std::string& buffer = panels_.text_buffers[id];
    ImGui::InputText(label, &buffer);
    if (ImGui::IsItemActive()) panels_.text_editing = id;
    else if (panels_.text_editing == id) panels_.text_editing = 0;
    if (ImGui::IsItemDeactivatedAfterEdit() && buffer != value) {
        const std::string typed = buffer;
        apply([&](Scene& sc) { set(sc, typed); });
    }
}

bool SceneEditor::apply(const std::function<void(Scene&)>& change) { return commit(change, false); }

namespace {

// "m/s^2" -> "m/s²" for the panel's labels.
std::string pretty_unit(const char* unit) {
    std::string u = unit;
    for (const auto& [from, to] : {std::pair<const char*, const char*>{"^2", "²"}, {"^3", "³"}, {"deg", "°"}})
        if (const std::size_t at = u.find(from); at != std::string::npos) u.replace(at, std::string(from).size(), to);
    return u;
}

std::string field_label(const schema::FieldInfo& f) {
    return f.unit[0] ? std::string(f.label) + " (" + pretty_unit(f.unit) + ")" : std::string(f.label);
}

// The row's help and, for numbers, its bounds (in the reader's words).
std::string field_help(const schema::FieldInfo& f) {
    switch (f.kind) {
        case schema::FieldKind::number:
        case schema::FieldKind::vec3:
        case schema::FieldKind::optional_number: return std::string(f.help) + " Allowed: " + bounds_text(f.bounds) + ".";
        case schema::FieldKind::bounded_vec3: return std::string(f.help) + " Length " + bounds_text(f.bounds) + ".";
        default: return f.help;
    }
}

void enum_combo(SceneEditor& ed, const char* label, int current, const schema::EnumNames& names,
                const std::function<void(Scene&, int)>& set) {
    if (!ImGui::BeginCombo(label, names.name(current))) return;
    for (int e = 0; e < names.count; ++e) {
        const bool selected = e == current;
        if (ImGui::Selectable(names.name(e), selected) && !selected) ed.apply([&](Scene& s) { set(s, e); });
        if (selected) ImGui::SetItemDefaultFocus();
    }
    ImGui::EndCombo();
}

}  // namespace

// An optional number: a checkbox sets it (starting at its lower bound) or makes it absent.
template <class S>
void edit_optional(SceneEditor& ed, const schema::Field<S>& f, const std::function<S&(Scene&)>& at,
                   const std::string& label, const std::string& help) {
    const auto p = std::get<std::optional<double> S::*>(f.member);
    const std::optional<double> value = at(ed.current()).*p;
    bool set = value.has_value();
    if (ImGui::Checkbox(("set " + std::string(f.info.label)).c_str(), &set))
        ed.apply([&](Scene& s) {
            if (set) at(s).*p = f.info.bounds.lo;
            else (at(s).*p).reset();
        });
    help_marker(help.c_str());
    if (value) ed.number(label.c_str(), *value, [&](Scene& s, double v) { at(s).*p = v; }, "%.6g", help.c_str());
}

template <class S>
void edit_field(SceneEditor& ed, const schema::Field<S>& f, const std::function<S&(Scene&)>& at) {
    using K = schema::FieldKind;
    // Each case copies only its member: the edit may replace the scene (and a copy of a whole
    // Scene would copy every listed particle, every frame).
    const S& current = at(ed.current());
    const std::string label = field_label(f.info), help = field_help(f.info);
    const auto& m = f.member;
    switch (f.info.kind) {
        case K::number: {
            const auto p = std::get<double S::*>(m);
            const double value = current.*p;
            ed.number(label.c_str(), value, [&](Scene& s, double v) { at(s).*p = v; }, "%.6g", help.c_str());
            break;
        }
        case K::vec3:
        case K::bounded_vec3:
        case K::direction: {
            const auto p = std::get<Vec3 S::*>(m);
            const Vec3 value = current.*p;
            ed.vec3(label.c_str(), value, [&](Scene& s, const Vec3& v) { at(s).*p = v; }, "%.4g", help.c_str());
            break;
        }
        case K::unsigned_integer: {
            const auto p = std::get<std::uint64_t S::*>(m);
            const std::uint64_t value = current.*p;
            ed.integer(label.c_str(), value, [&](Scene& s, std::uint64_t v) { at(s).*p = v; }, help.c_str());
            break;
        }
        case K::boolean: {
            const auto p = std::get<bool S::*>(m);
            bool on = current.*p;
            if (ImGui::Checkbox(label.c_str(), &on)) ed.apply([&](Scene& s) { at(s).*p = on; });
            help_marker(help.c_str());
            break;
        }
        case K::string: {
            const auto p = std::get<std::string S::*>(m);
            const std::string value = current.*p;
            ed.text(label.c_str(), value, [&](Scene& s, const std::string& v) { at(s).*p = v; });
            break;
        }
        case K::enumeration: {
            const auto& e = std::get<schema::EnumAccess<S>>(m);
            const int value = e.get(current);
            enum_combo(ed, label.c_str(), value, f.info.names, [&](Scene& s, int v) { e.set(at(s), v); });
            help_marker(help.c_str());
            break;
        }
        case K::optional_number: edit_optional(ed, f, at, label, help); break;
        case K::format_tag:
        case K::version_tag: break;  // constants, not edited
    }
}

template <class S>
void edit_fields(SceneEditor& ed, const std::function<S&(Scene&)>& at) {
    const auto rows = schema::SectionSchema<S>::rows;
    // A field whose row names the values of the section's enumeration (its first row) it applies to
    // is shown only for those, e.g. wind.period only for gusts.
    int selected = -1;
    if (!rows.empty() && rows.front().info.kind == schema::FieldKind::enumeration)
        selected = std::get<schema::EnumAccess<S>>(rows.front().member).get(at(ed.current()));
    for (const schema::Field<S>& f : rows)
        if (selected < 0 || (f.info.shown_for >> selected & 1u)) edit_field(ed, f, at);
}

#define PL_EDIT_FIELDS(S)                                                                                   \
    template void edit_fields<S>(SceneEditor&, const std::function<S&(Scene&)>&);                          \
    template void edit_field<S>(SceneEditor&, const schema::Field<S>&, const std::function<S&(Scene&)>&);
PL_EDIT_FIELDS(Scene)
PL_EDIT_FIELDS(Room)
PL_EDIT_FIELDS(World)
PL_EDIT_FIELDS(ParticleSpec)
PL_EDIT_FIELDS(Emitter)
PL_EDIT_FIELDS(Variant)
PL_EDIT_FIELDS(IntegratorSettings)
PL_EDIT_FIELDS(CollisionSettings)
#undef PL_EDIT_FIELDS

void edit_drag_section(SceneEditor& ed, const std::function<DragSettings&(Scene&)>& at) {
    edit_fields(ed, at);
    const DragModel model = at(ed.current()).model;
    const ReRange valid = drag_validity(model);
    if (model != DragModel::none) ImGui::TextDisabled("valid for %.3g < Re < %.3g", valid.lo, valid.hi);
}

void edit_wind_section(SceneEditor& ed, const std::function<WindSettings&(Scene&)>& at, bool drag_on) {
    if (at(ed.current()).kind != WindKind::none && !drag_on)
        ImGui::TextColored({1.0f, 0.8f, 0.3f, 1.0f}, "Drag is off: wind has no effect.");
    edit_fields(ed, at);
}

void edit_air_section(SceneEditor& ed, const std::function<Air&(Scene&)>& at) { edit_fields(ed, at); }

void edit_contact_section(SceneEditor& ed, const std::function<ContactSettings&(Scene&)>& at) { edit_fields(ed, at); }

void edit_integrator_section(SceneEditor& ed, const std::function<IntegratorSettings&(Scene&)>& at) {
    edit_fields(ed, at);
    const Method method = at(ed.current()).method;
    const double limit = stability_limit(at(ed.current()));
    if (std::isfinite(limit)) ImGui::TextDisabled("order %d, stable for dt k < %.3g", method_order(method), limit);
    else ImGui::TextDisabled("order %d, stable for any dt k", method_order(method));
    if (keeps_bounce_energy(method)) ImGui::TextDisabled("elastic bounces keep their energy");
    else ImGui::TextDisabled("gains speed on every bounce arc: rests only for dt <= rest_speed (1-e)/(e g)");
}

}  // namespace pl::ui
