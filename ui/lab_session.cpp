#include "ui/lab_session.hpp"

namespace pl::ui {

bool LabSession::load(const std::filesystem::path& file) {
    LoadResult r = load_preset(file);
    if (!r.ok()) {
        error_popup = "Could not load " + file.string() + ":\n" + r.error_text() + "\nThe current scene is kept.";
        return false;
    }
    preset_path = file;
    dirty = false;
    apply_scene(*r.scene);
    status_message = "Loaded " + file.filename().string();
    return true;
}

void LabSession::apply_scene(const Scene& s) {
    scene = s;
    experiment = std::make_unique<Experiment>(scene);
    selected_particle = 0;
    if (selected_variant >= static_cast<int>(experiment->variant_count())) selected_variant = 0;
    history.reset();
}

}  // namespace pl::ui
