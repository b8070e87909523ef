#include "ui/scene_editor.hpp"

#include "physics/model/drag.hpp"
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
    s_.apply_scene(edited);
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

void SceneEditor::integer(const char* label, std::uint64_t value, std::uint64_t max, const char* path,
                          const std::function<void(Scene&, std::uint64_t)>& set, const char* help) {
    const std::optional<double> v = input_number(panels_.fields, label, static_cast<double>(value), "%.0f", help);
    if (!v) return;
    if (!(*v >= 0.0 && *v <= static_cast<double>(max) && std::floor(*v) == *v)) {
        panels_.fields.resolve(std::string(path) + ": must be a whole number in [0, " + std::to_string(max) + "], got " +
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

template <class Enum, std::size_t N>
void enum_combo(SceneEditor& ed, const char* label, Enum current, const Enum (&values)[N],
                const std::function<void(Scene&, Enum)>& set) {
    if (!ImGui::BeginCombo(label, to_string(current))) return;
    for (Enum e : values) {
        const bool selected = e == current;
        if (ImGui::Selectable(to_string(e), selected) && !selected) ed.apply([&](Scene& s) { set(s, e); });
        if (selected) ImGui::SetItemDefaultFocus();
    }
    ImGui::EndCombo();
}

constexpr DragModel all_drag_models[] = {DragModel::none, DragModel::linear, DragModel::quadratic, DragModel::sphere_re};
constexpr WindKind all_wind_kinds[] = {WindKind::none, WindKind::constant, WindKind::gust, WindKind::shear, WindKind::vortex};
constexpr Method all_methods[] = {Method::explicit_euler, Method::semi_implicit_euler, Method::velocity_verlet,
                                  Method::rk4,            Method::dopri5,              Method::exponential};

}  // namespace

void edit_drag_section(SceneEditor& ed, const std::function<DragSettings&(Scene&)>& at) {
    const DragSettings d = at(ed.current());
    enum_combo<DragModel>(ed, "drag model", d.model, all_drag_models, [&](Scene& s, DragModel m) { at(s).model = m; });
    help_marker("none: no air resistance. linear: Stokes, F = -6 pi mu R v (or an explicit b). "
                "quadratic: Newton, F = -1/2 rho Cd A |v| v. sphere_re: Cd(Re) for a smooth sphere over the "
                "whole Reynolds range (Morrison 2013).");
    const ReRange valid = drag_validity(d.model);
    if (d.model != DragModel::none) ImGui::TextDisabled("valid for %.3g < Re < %.3g", valid.lo, valid.hi);
    if (d.model == DragModel::quadratic)
        ed.number("Cd", d.cd, [&](Scene& s, double v) { at(s).cd = v; }, "%.4g", "Drag coefficient, 0.47 for a smooth sphere.");
    if (d.model == DragModel::linear) {
        bool stokes = !d.linear_b.has_value();
        if (ImGui::Checkbox("Stokes b = 6 pi mu R", &stokes))
            ed.apply([&](Scene& s) {
                if (stokes) at(s).linear_b.reset();
                else at(s).linear_b = 0.01;
            });
        if (d.linear_b)
            ed.number("b (N s/m)", *d.linear_b, [&](Scene& s, double v) { at(s).linear_b = v; }, "%.4g",
                      "Linear drag coefficient: F = -b v_rel.");
    }
}

void edit_wind_section(SceneEditor& ed, const std::function<WindSettings&(Scene&)>& at, bool drag_on) {
    const WindSettings w = at(ed.current());
    enum_combo<WindKind>(ed, "wind", w.kind, all_wind_kinds, [&](Scene& s, WindKind k) { at(s).kind = k; });
    if (w.kind != WindKind::none && !drag_on)
        ImGui::TextColored({1.0f, 0.8f, 0.3f, 1.0f}, "Drag is off: wind has no effect.");
    switch (w.kind) {
        case WindKind::none: break;
        case WindKind::constant:
            ed.vec3("velocity (m/s)", w.velocity, [&](Scene& s, const Vec3& v) { at(s).velocity = v; });
            break;
        case WindKind::gust:
            ed.vec3("mean (m/s)", w.velocity, [&](Scene& s, const Vec3& v) { at(s).velocity = v; });
            ed.vec3("amplitude (m/s)", w.gust_amplitude, [&](Scene& s, const Vec3& v) { at(s).gust_amplitude = v; });
            ed.number("period (s)", w.gust_period_s, [&](Scene& s, double v) { at(s).gust_period_s = v; });
            ed.integer("seed", w.gust_seed, std::uint64_t{1} << 53, "world.wind.seed",
                       [&](Scene& s, std::uint64_t v) { at(s).gust_seed = v; }, "Same seed, same gusts.");
            break;
        case WindKind::shear:
            ed.vec3("at ref. height (m/s)", w.velocity, [&](Scene& s, const Vec3& v) { at(s).velocity = v; });
            ed.number("ref. height (m)", w.reference_height_m, [&](Scene& s, double v) { at(s).reference_height_m = v; });
            ed.number("exponent", w.shear_exponent, [&](Scene& s, double v) { at(s).shear_exponent = v; }, "%.4g",
                      "Power-law boundary layer |w| ~ (height / ref. height)^exponent; 1/7 for open terrain.");
            break;
        case WindKind::vortex:
            ed.vec3("centre (m)", w.vortex_center, [&](Scene& s, const Vec3& v) { at(s).vortex_center = v; });
            ed.vec3("axis", w.vortex_axis, [&](Scene& s, const Vec3& v) { at(s).vortex_axis = v; });
            ed.number("max speed (m/s)", w.vortex_max_speed, [&](Scene& s, double v) { at(s).vortex_max_speed = v; });
            ed.number("core radius (m)", w.vortex_core_radius_m, [&](Scene& s, double v) { at(s).vortex_core_radius_m = v; },
                      "%.4g", "Rankine vortex: the swirl rises linearly to max speed at the core radius, then falls as 1/r.");
            break;
    }
}

void edit_air_section(SceneEditor& ed, const std::function<Air&(Scene&)>& at) {
    const Air a = at(ed.current());
    ed.number("density (kg/m³)", a.density_kg_m3, [&](Scene& s, double v) { at(s).density_kg_m3 = v; }, "%.5g",
              "1.225 at sea level (ISA, 15 C); about 0.74 at 5000 m.");
    ed.number("viscosity (Pa s)", a.viscosity_pa_s, [&](Scene& s, double v) { at(s).viscosity_pa_s = v; }, "%.4g",
              "Dynamic viscosity, 1.81e-5 for air at 15 C.");
}

void edit_contact_section(SceneEditor& ed, const std::function<ContactSettings&(Scene&)>& at) {
    const ContactSettings c = at(ed.current());
    ed.number("restitution e", c.restitution, [&](Scene& s, double v) { at(s).restitution = v; }, "%.4g",
              "Normal rebound speed / impact speed, 0 (sticks) .. 1 (no loss).");
    ed.number("friction mu", c.friction, [&](Scene& s, double v) { at(s).friction = v; }, "%.4g",
              "Coulomb friction coefficient on the walls, >= 0.");
    ed.number("rest speed (m/s)", c.rest_speed, [&](Scene& s, double v) { at(s).rest_speed = v; }, "%.4g",
              "A rebound slower than this ends in rest on the wall.");
}

void edit_integrator_section(SceneEditor& ed, const std::function<IntegratorSettings&(Scene&)>& at) {
    const IntegratorSettings g = at(ed.current());
    enum_combo<Method>(ed, "method", g.method, all_methods, [&](Scene& s, Method m) { at(s).method = m; });
    const double limit = method_stability_limit(g.method);
    if (std::isfinite(limit)) ImGui::TextDisabled("order %d, stable for dt k < %.3g", method_order(g.method), limit);
    else ImGui::TextDisabled("order %d, stable for any dt k", method_order(g.method));
    ed.number("dt (s)", g.dt, [&](Scene& s, double v) { at(s).dt = v; }, "%.6g", "The fixed step every run advances by.");
    if (g.method == Method::dopri5) {
        bool adaptive = g.adaptive;
        if (ImGui::Checkbox("adaptive (error control)", &adaptive)) ed.apply([&](Scene& s) { at(s).adaptive = adaptive; });
        if (g.adaptive) {
            ed.number("rtol", g.rtol, [&](Scene& s, double v) { at(s).rtol = v; }, "%.3g");
            ed.number("atol (m, m/s)", g.atol, [&](Scene& s, double v) { at(s).atol = v; }, "%.3g");
        }
    }
}

}  // namespace pl::ui
