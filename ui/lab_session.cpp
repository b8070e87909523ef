#include "ui/lab_session.hpp"

#include "physics/model/emitter.hpp"
#include "physics/studies/resource_estimate.hpp"
#include "ui/panel_state.hpp"

#include <new>
#include <stdexcept>

namespace pl::ui {

std::optional<ParticleSpec> first_particle(const Scene& scene) {
    if (!scene.particles.empty()) return scene.particles.front();
    if (!scene.emitter || scene.emitter->count == 0) return std::nullopt;
    return emit_particles(*scene.emitter, scene.room, 1).front();
}

void LabSession::request(const PendingAction& a) {
    if (dirty) pending = a;
    else perform(a);
}

bool LabSession::perform(const PendingAction& a) {
    pending.reset();
    switch (a.kind) {
        case PendingAction::Kind::quit: requests.quit = true; return true;
        case PendingAction::Kind::open: return load(a.file);
        case PendingAction::Kind::revert:
            if (!load(a.file)) return false;
            status_message = "Reverted to " + a.file.filename().string();
            return true;
    }
    return false;
}

bool LabSession::load(const std::filesystem::path& file) {
    LoadResult r = load_preset(file);
    const std::string refused = r.ok() ? open_preset(*r.scene, file) : r.error_text();
    if (!refused.empty()) {
        error_popup = "Could not load " + file.string() + ":\n" + refused + "\nThe current scene is kept.";
        return false;
    }
    status_message = "Loaded " + file.filename().string();
    return true;
}

std::string LabSession::open_preset(const Scene& s, const std::filesystem::path& file) {
    if (std::string refused = apply_scene(s); !refused.empty()) return refused;
    preset_path = file;
    dirty = false;
    if (const std::optional<ParticleSpec> p0 = first_particle(s)) launch_velocity = p0->velocity;
    if (panels) {
        panels->launch_from_velocity = true;  // the Launch panel's sliders follow
        panels->presets_scanned = false;      // the preset list marks the file now open (or shows a new one)
    }
    return "";
}

std::string LabSession::apply_scene(const Scene& s) {
    // Refused before building: a scene past the machine's memory would otherwise end the app
    // (or drive the machine into swap) half-way through allocating.
    if (std::string refused = memory_refusal(work_of(s)); !refused.empty()) return "this scene " + refused;
    std::unique_ptr<Experiment> built;
    try {
        built = std::make_unique<Experiment>(s);
    } catch (const std::bad_alloc&) {
        return "building this scene ran out of memory; use fewer particles or variants";
    } catch (const std::length_error& e) {
        return std::string("building this scene failed: ") + e.what() + "; use fewer particles or variants";
    }
    scene = s;
    experiment = std::move(built);
    selected_particle = 0;
    if (selected_variant >= static_cast<int>(experiment->variant_count())) selected_variant = 0;
    history.reset();
    return "";
}

}  // namespace pl::ui
