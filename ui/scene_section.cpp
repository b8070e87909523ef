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
            ed.vec3("position (m)", p.position, [i](Scene& sc, const Vec3& v) { sc.particles[i].position = v; });
            ed.vec3("velocity (m/s)", p.velocity, [i](Scene& sc, const Vec3& v) { sc.particles[i].velocity = v; });
            ed.number("mass (kg)", p.mass, [i](Scene& sc, double v) { sc.particles[i].mass = v; });
            ed.number("radius (m)", p.radius, [i](Scene& sc, double v) { sc.particles[i].radius = v; });
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
    const Emitter e = *s.scene.emitter;
    ed.integer("count", e.count, max_preset_particles, "emitter.count",
               [](Scene& sc, std::uint64_t v) { sc.emitter->count = static_cast<std::size_t>(v); },
               "Particles the emitter creates (seeded: the same seed gives the same particles).");
    ed.integer("seed", e.seed, std::uint64_t{1} << 53, "emitter.seed", [](Scene& sc, std::uint64_t v) { sc.emitter->seed = v; });
    ed.vec3("region min (m)", e.region_min, [](Scene& sc, const Vec3& v) { sc.emitter->region_min = v; });
    ed.vec3("region max (m)", e.region_max, [](Scene& sc, const Vec3& v) { sc.emitter->region_max = v; });
    ed.number("speed min (m/s)", e.speed_min, [](Scene& sc, double v) { sc.emitter->speed_min = v; });
    ed.number("speed max (m/s)", e.speed_max, [](Scene& sc, double v) { sc.emitter->speed_max = v; });
    ed.vec3("direction", e.direction, [](Scene& sc, const Vec3& v) { sc.emitter->direction = v; });
    ed.number("spread (°)", e.spread_deg, [](Scene& sc, double v) { sc.emitter->spread_deg = v; });
    ed.number("mass min (kg)", e.mass_min, [](Scene& sc, double v) { sc.emitter->mass_min = v; });
    ed.number("mass max (kg)", e.mass_max, [](Scene& sc, double v) { sc.emitter->mass_max = v; });
    ed.number("radius min (m)", e.radius_min, [](Scene& sc, double v) { sc.emitter->radius_min = v; });
    ed.number("radius max (m)", e.radius_max, [](Scene& sc, double v) { sc.emitter->radius_max = v; });
}

}  // namespace

void draw_scene_section(LabSession& s) {
    SceneEditor ed(s);
    ed.text("name", s.scene.name, [](Scene& sc, const std::string& v) { sc.name = v; });
    ed.text("description", s.scene.description, [](Scene& sc, const std::string& v) { sc.description = v; });

    if (ImGui::TreeNode("Room")) {
        ed.vec3("centre (m)", s.scene.room.center, [](Scene& sc, const Vec3& v) { sc.room.center = v; });
        ed.vec3("size (m)", s.scene.room.size, [](Scene& sc, const Vec3& v) { sc.room.size = v; }, "%.4g",
                "Edge lengths of the box; every particle must fit inside.");
        ImGui::TreePop();
    }
    if (ImGui::TreeNode("Gravity and air")) {
        ed.vec3("gravity (m/s²)", s.scene.world.gravity, [](Scene& sc, const Vec3& v) { sc.world.gravity = v; }, "%.4g",
                "y is up: (0, -9.81, 0) on Earth.");
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
