#include "ui/palette.hpp"
#include "ui/panel_state.hpp"
#include "ui/plot.hpp"
#include "ui/scene_editor.hpp"
#include "ui/sections.hpp"

#include <imgui.h>

#include <algorithm>

namespace pl::ui {
namespace {

// A label no other variant has: "<base>", "<base> 2", "<base> 3", ...
std::string unique_label(const Scene& sc, const std::string& base) {
    auto taken = [&](const std::string& l) {
        return std::any_of(sc.variants.begin(), sc.variants.end(), [&](const Variant& v) { return v.label == l; });
    };
    if (!taken(base)) return base;
    for (int n = 2;; ++n)
        if (!taken(base + " " + std::to_string(n))) return base + " " + std::to_string(n);
}

// One section a variant may override: a checkbox to override it, then its fields.
template <class Section>
void override_section(SceneEditor& ed, std::size_t v, const char* name, std::optional<Section> Variant::*member,
                      Section (*base)(const Scene&), void (*edit)(SceneEditor&, std::size_t)) {
    const bool overridden = (ed.scene().variants[v].*member).has_value();
    bool on = overridden;
    if (ImGui::Checkbox(name, &on))
        ed.apply([&](Scene& sc) {
            if (on) sc.variants[v].*member = base(sc);
            else (sc.variants[v].*member).reset();
        });
    if (!overridden) {
        ImGui::SameLine();
        ImGui::TextDisabled("(as the scene)");
        return;
    }
    ImGui::Indent();
    ImGui::PushID(name);
    edit(ed, v);
    ImGui::PopID();
    ImGui::Unindent();
}

}  // namespace

void draw_variants_section(LabSession& s) {
    SceneEditor ed(s);
    const std::size_t n = s.scene.variants.size();
    if (n == 0) ImGui::TextWrapped("The scene runs alone. Add variants to compare drag models, integrators, time "
                                   "steps or wind side by side: each overrides whole sections of the scene.");
    for (std::size_t v = 0; v < n; ++v) {
        ImGui::PushID(static_cast<int>(v));
        const Rgba c = series_color(static_cast<int>(v));
        ImGui::ColorButton("##colour", ImVec4(c[0], c[1], c[2], c[3]), ImGuiColorEditFlags_NoTooltip, ImVec2(12, 12));
        ImGui::SameLine();
        if (ImGui::Selectable(s.scene.variants[v].label.c_str(), s.selected_variant == static_cast<int>(v)))
            s.selected_variant = static_cast<int>(v);
        ImGui::PopID();
    }
    if (ImGui::Button(n == 0 ? "Add variants" : "Add")) {
        ed.apply([](Scene& sc) {
            // The first variant added also keeps the scene itself as the baseline.
            if (sc.variants.empty()) sc.variants.push_back(Variant{"baseline", {}, {}, {}, {}, {}, {}});
            Variant added;
            added.label = unique_label(sc, "variant");
            sc.variants.push_back(added);
        });
        s.selected_variant = static_cast<int>(s.scene.variants.size()) - 1;
    }
    const bool selected = s.selected_variant >= 0 && static_cast<std::size_t>(s.selected_variant) < s.scene.variants.size();
    const std::size_t sel = selected ? static_cast<std::size_t>(s.selected_variant) : 0;
    ImGui::SameLine();
    ImGui::BeginDisabled(!selected);
    if (ImGui::Button("Duplicate") && selected) {
        ed.apply([&](Scene& sc) {
            Variant copy = sc.variants[sel];
            copy.label = unique_label(sc, copy.label + " copy");
            sc.variants.insert(sc.variants.begin() + static_cast<std::ptrdiff_t>(sel) + 1, copy);
        });
        s.selected_variant = static_cast<int>(sel) + 1;
    }
    ImGui::SameLine();
    if (ImGui::Button("Remove") && selected) {
        const int keep = static_cast<int>(sel) - 1;
        ed.apply([&](Scene& sc) { sc.variants.erase(sc.variants.begin() + static_cast<std::ptrdiff_t>(sel)); });
        s.selected_variant = std::max(0, keep);
    }
    ImGui::EndDisabled();
    if (!selected || s.scene.variants.empty()) return;

    ImGui::Separator();
    ImGui::PushID("variant_edit");
    edit_fields<Variant>(ed, [sel](Scene& sc) -> Variant& { return sc.variants[sel]; });
    override_section<DragSettings>(ed, sel, "drag", &Variant::drag, [](const Scene& sc) { return sc.drag; },
                                   [](SceneEditor& e, std::size_t v) {
                                       edit_drag_section(e, [v](Scene& sc) -> DragSettings& { return *sc.variants[v].drag; });
                                   });
    override_section<WindSettings>(ed, sel, "wind", &Variant::wind, [](const Scene& sc) { return sc.world.wind; },
                                   [](SceneEditor& e, std::size_t v) {
                                       const Variant& var = e.scene().variants[v];
                                       const DragModel drag = var.drag ? var.drag->model : e.scene().drag.model;
                                       edit_wind_section(e, [v](Scene& sc) -> WindSettings& { return *sc.variants[v].wind; },
                                                         drag != DragModel::none);
                                   });
    override_section<Air>(ed, sel, "air", &Variant::air, [](const Scene& sc) { return sc.world.air; },
                          [](SceneEditor& e, std::size_t v) {
                              edit_air_section(e, [v](Scene& sc) -> Air& { return *sc.variants[v].air; });
                          });
    override_section<ContactSettings>(ed, sel, "contact", &Variant::contact, [](const Scene& sc) { return sc.contact; },
                                      [](SceneEditor& e, std::size_t v) {
                                          edit_contact_section(e, [v](Scene& sc) -> ContactSettings& { return *sc.variants[v].contact; });
                                      });
    override_section<CollisionSettings>(ed, sel, "collisions", &Variant::collisions,
                                        [](const Scene& sc) { return sc.collisions; }, [](SceneEditor& e, std::size_t v) {
                                            edit_fields<CollisionSettings>(e, [v](Scene& sc) -> CollisionSettings& {
                                                return *sc.variants[v].collisions;
                                            });
                                        });
    override_section<IntegratorSettings>(ed, sel, "integrator", &Variant::integrator,
                                         [](const Scene& sc) { return sc.integrator; }, [](SceneEditor& e, std::size_t v) {
                                             edit_integrator_section(e, [v](Scene& sc) -> IntegratorSettings& {
                                                 return *sc.variants[v].integrator;
                                             });
                                         });
    ImGui::PopID();
}

}  // namespace pl::ui
