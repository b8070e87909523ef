#include "app/state_dump.hpp"

#include <nlohmann/json.hpp>

#include <fstream>

namespace pl::app {

namespace {

nlohmann::json vec3(const Vec3& v) { return nlohmann::json::array({v.x, v.y, v.z}); }

nlohmann::json variant_json(const Simulation& sim) {
    const ParticleState& st = sim.state();
    nlohmann::json particles = nlohmann::json::array();
    for (std::size_t i = 0; i < st.size(); ++i)
        particles.push_back({{"position", vec3(st.position(i))},
                             {"velocity", vec3(st.velocity(i))},
                             {"resting_walls", st.resting[i]},
                             {"frozen", st.frozen[i] != 0}});
    return {{"label", sim.model().label}, {"t", sim.time()}, {"steps", sim.step_count()}, {"particles", particles}};
}

}  // namespace

std::string write_state_dump(const std::filesystem::path& file, const ui::LabSession& s, long frames) {
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
    j["view"] = {{"trails", s.show_trails}, {"velocity", s.show_velocity}, {"wind", s.show_wind}, {"split", s.split_view}};
    j["t"] = s.experiment ? s.experiment->time() : 0.0;
    j["base_steps"] = s.experiment ? s.experiment->base_steps() : 0;
    nlohmann::json variants = nlohmann::json::array();
    if (s.experiment)
        for (const Simulation& sim : s.experiment->runs()) variants.push_back(variant_json(sim));
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
