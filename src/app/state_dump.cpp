#include "app/state_dump.hpp"

#include "app/picking.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>

namespace pl::app {

namespace {

nlohmann::json vec3(const Vec3& v) { return nlohmann::json::array({v.x, v.y, v.z}); }

// Where particle i appears in the window (ImGui coordinates = window pixels), or null.
nlohmann::json screen_position(const ViewSnapshot& view, std::size_t variant, const Vec3& x) {
    for (const ViewPane& pane : view.panes) {
        if (pane.variant && *pane.variant != variant) continue;
        const CameraMatrices cam = camera_matrices(view.camera, pane.rect.w / std::max(pane.rect.h, 1.0f));
        if (auto p = project(cam, pane.rect, glm::vec3(x)); p && pane.rect.contains(p->x, p->y))
            return nlohmann::json::array({p->x, p->y});
    }
    return nullptr;
}

nlohmann::json variant_json(const Simulation& sim, std::size_t variant, const ViewSnapshot& view) {
    const ParticleState& st = sim.state();
    nlohmann::json particles = nlohmann::json::array();
    for (std::size_t i = 0; i < st.size(); ++i)
        particles.push_back({{"position", vec3(st.position(i))},
                             {"velocity", vec3(st.velocity(i))},
                             {"resting_walls", st.resting[i]},
                             {"frozen", st.frozen[i] != 0},
                             {"screen", screen_position(view, variant, st.position(i))}});
    return {{"label", sim.model().label}, {"t", sim.time()}, {"steps", sim.step_count()}, {"particles", particles}};
}

}  // namespace

std::string write_state_dump(const std::filesystem::path& file, const ui::LabSession& s, long frames,
                             const ViewSnapshot& view) {
    nlohmann::json j;
    j["frames"] = frames;
    j["preset"] = s.preset_path.string();
    j["dirty"] = s.dirty;
    j["paused"] = s.paused;
    j["time_scale"] = s.time_scale;
    j["selected_particle"] = s.selected_particle;
    j["selected_variant"] = s.selected_variant;
    j["launch_velocity"] = vec3(s.launch_velocity);
    j["error_popup"] = s.error_popup;
    j["show_help"] = s.show_help;
    const OrbitCamera& c = view.camera;
    nlohmann::json panes = nlohmann::json::array();
    for (const ViewPane& p : view.panes) panes.push_back({p.rect.x, p.rect.y, p.rect.w, p.rect.h});
    j["view"] = {{"trails", s.show_trails},
                 {"velocity", s.show_velocity},
                 {"wind", s.show_wind},
                 {"split", s.split_view},
                 {"camera", {{"target", {c.target.x, c.target.y, c.target.z}}, {"yaw", c.yaw}, {"pitch", c.pitch},
                             {"distance", c.distance}}},
                 {"panes", panes}};
    j["t"] = s.experiment ? s.experiment->time() : 0.0;
    j["base_steps"] = s.experiment ? s.experiment->base_steps() : 0;
    nlohmann::json variants = nlohmann::json::array();
    if (s.experiment)
        for (std::size_t v = 0; v < s.experiment->variant_count(); ++v)
            variants.push_back(variant_json(s.experiment->run(v), v, view));
    j["variants"] = variants;

    const std::filesystem::path tmp = file.string() + ".tmp";
    {
        std::ofstream out(tmp, std::ios::trunc);
        if (!out) return "cannot write " + tmp.string();
        out << j.dump(1) << '\n';
        if (!out.flush()) return "cannot write " + tmp.string();
    }
    std::error_code ec;
    std::filesystem::rename(tmp, file, ec);
    if (ec) return "cannot rename " + tmp.string() + " to " + file.string() + ": " + ec.message();
    return {};
}

}  // namespace pl::app
