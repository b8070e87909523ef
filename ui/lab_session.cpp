#include "ui/lab_session.hpp"

#include "ui/panel_state.hpp"

namespace pl::ui {

std::optional<ParticleSpec> first_particle(const Scene& scene) {
    if (!scene.particles.empty()) return scene.particles.front();
    if (!scene.emitter || scene.emitter->count == 0) return std::nullopt;
    return initial_particles(scene).front();
}

bool LabSession::load(const std::filesystem::path& file) {
    LoadResult r = load_preset(file);
    if (!r.ok()) {
        error_popup = "Could not load " + file.string() + ":\n" + r.error_text() + "\nThe current scene is kept.";
        return false;
    }
    open_preset(*r.scene, file);
    status_message = "Loaded " + file.filename().string();
    return true;
}

void LabSession::open_preset(const Scene& s, const std::filesystem::path& file) {
    preset_path = file;
    dirty = false;
    apply_scene(s);
    if (const std::optional<ParticleSpec> p0 = first_particle(s)) launch_velocity = p0->velocity;
    if (panels) panels->launch_from_velocity = true;  // the Launch panel's sliders follow
}

void LabSession::apply_scene(const Scene& s) {
    scene = s;
    experiment = std::make_unique<Experiment>(scene);
    selected_particle = 0;
    if (selected_variant >= static_cast<int>(experiment->variant_count())) selected_variant = 0;
    history.reset();
}

}  // namespace pl::ui
