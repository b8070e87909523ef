#include "physics/model/emitter.hpp"
#include "io/preset_io.hpp"
#include "ui/panel_state.hpp"
#include "ui/scene_editor.hpp"
#include "ui/sections.hpp"

#include <imgui.h>

#include <algorithm>

namespace pl::ui {
namespace {

void edit_particles(SceneEditor& ed, LabSession& s) {
    const std::vector<ParticleSpec> particles = s.scene.particles;
    for (std::size_t i = 0; i < particles.size() && i < 64; ++i) {
        ImGui::PushID(static_cast<int>(i));
        const ParticleSpec& p = particles[i];
        const bool open = ImGui::TreeNode("particle", "particle %zu  (m = %.3g kg, r = %.3g m)", i, p.mass, p.radius);
        if (open) {
            edit_fields<ParticleSpec>(ed, [i](Scene& sc) -> ParticleSpec& { return sc.particles[i]; });
            if (ImGui::SmallButton("Remove particle"))
                ed.apply([i](Scene& sc) { sc.particles.erase(sc.particles.begin() + static_cast<std::ptrdiff_t>(i)); });
            ImGui::TreePop();
        }
        ImGui::PopID();
    }
    if (particles.size() > 64) ImGui::TextDisabled("... and %zu more (edit the file for those)", particles.size() - 64);
    if (ImGui::Button("Add particle")) {
        ed.apply([](Scene& sc) {
            // A copy of the last one (or a default ball) in the middle of the room, launched upwards.
            ParticleSpec p = sc.particles.empty() ? ParticleSpec{} : sc.particles.back();
            p.position = sc.room.center;
            p.velocity = {1.0, 3.0, 0.5};
            sc.particles.push_back(p);
        });
    }

    bool has_emitter = s.scene.emitter.has_value();
    if (ImGui::Checkbox("emitter (many particles)", &has_emitter))
        ed.apply([&](Scene& sc) {
            if (has_emitter) {
                Emitter e;
                e.count = 100;
                e.region_min = sc.room.center - 0.25 * sc.room.size;
                e.region_max = sc.room.center + 0.25 * sc.room.size;
                sc.emitter = e;
            } else {
                sc.emitter.reset();
            }
        });
    if (!s.scene.emitter) return;
    edit_fields<Emitter>(ed, [](Scene& sc) -> Emitter& { return *sc.emitter; });
}

}  // namespace

void draw_scene_section(LabSession& s) {
    SceneEditor ed(s);
    edit_fields<Scene>(ed, [](Scene& sc) -> Scene& { return sc; });

    if (ImGui::TreeNode("Room")) {
        edit_fields<Room>(ed, [](Scene& sc) -> Room& { return sc.room; });
        ImGui::TreePop();
    }
    if (ImGui::TreeNode("Gravity and air")) {
        edit_fields<World>(ed, [](Scene& sc) -> World& { return sc.world; });
        edit_air_section(ed, [](Scene& sc) -> Air& { return sc.world.air; });
        ImGui::TreePop();
    }
    if (ImGui::TreeNode("Drag")) {
        edit_drag_section(ed, [](Scene& sc) -> DragSettings& { return sc.drag; });
        ImGui::TreePop();
    }
    if (ImGui::TreeNode("Wind")) {
        edit_wind_section(ed, [](Scene& sc) -> WindSettings& { return sc.world.wind; }, s.scene.drag.model != DragModel::none);
        ImGui::TreePop();
    }
    if (ImGui::TreeNode("Contact")) {
        edit_contact_section(ed, [](Scene& sc) -> ContactSettings& { return sc.contact; });
        ImGui::TreePop();
    }
    if (ImGui::TreeNode("Collisions")) {
        edit_fields<CollisionSettings>(ed, [](Scene& sc) -> CollisionSettings& { return sc.collisions; });
        ImGui::TreePop();
    }
    if (ImGui::TreeNode("Integrator")) {
        edit_integrator_section(ed, [](Scene& sc) -> IntegratorSettings& { return sc.integrator; });
        ImGui::TreePop();
    }
    if (ImGui::TreeNode("Particles")) {
        edit_particles(ed, s);
        ImGui::TreePop();
    }
    if (!s.scene.variants.empty())
        ImGui::TextDisabled("Variants override some of these sections (see Variants).");
}

}  // namespace pl::ui
