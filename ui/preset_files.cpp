// Saving and opening presets with care: a shipped preset is read-only (Save becomes Save As into
// the user's preset folder), Save As and Open go through the file dialog (ui/file_dialog.hpp),
// which asks before it overwrites. Every save is atomic (io save_preset: io/atomic_output).
#include "io/preset_io.hpp"
#include "ui/file_dialog.hpp"
#include "ui/lab_ui.hpp"
#include "ui/panel_state.hpp"
#include "ui/sections.hpp"

#include <cstdlib>
#include <system_error>

namespace pl::ui {

namespace fs = std::filesystem;

fs::path user_preset_dir() {
    if (const char* xdg = std::getenv("XDG_DATA_HOME"); xdg && *xdg) return fs::path(xdg) / "particle-lab" / "presets";
    if (const char* home = std::getenv("HOME"); home && *home)
        return fs::path(home) / ".local" / "share" / "particle-lab" / "presets";
    return {};
}

bool is_shipped_preset(const LabSession& s, const fs::path& file) {
    if (file.empty() || s.preset_dir.empty()) return false;
    std::error_code ec;
    const fs::path user = user_preset_dir();
    if (!user.empty() && fs::equivalent(user, s.preset_dir, ec)) return false;
    return fs::equivalent(file.parent_path().empty() ? fs::path(".") : file.parent_path(), s.preset_dir, ec);
}

bool save_scene_to(LabSession& s, const fs::path& file) {
    const SaveResult r = save_preset(file, s.scene);
    if (!r.ok) {
        s.error_popup = "Could not save " + file.string() + ":\n" + r.error + "\nNothing was lost: the scene is still open.";
        return false;
    }
    s.preset_path = file;
    s.dirty = false;
    s.status_message = "Saved " + file.string();
    panels_of(s).presets_scanned = false;  // a new file shows in the preset list
    return true;
}

void begin_save_as(LabSession& s, std::optional<PendingAction> then) {
    PanelState& p = panels_of(s);
    p.after_save = std::move(then);
    const fs::path dir = user_preset_dir();
    const std::string name = s.preset_path.empty() ? s.scene.name : s.preset_path.stem().string();
    const bool own = !s.preset_path.empty() && !is_shipped_preset(s, s.preset_path);
    const char* title = is_shipped_preset(s, s.preset_path) ? "Save a copy (shipped presets are read-only)" : "Save preset as";
    open_file_dialog(p.file_dialog, FileDialog::Mode::save, FilePurpose::save_preset, title,
                     own ? s.preset_path.parent_path() : dir, bad_file_name(name).empty() ? name + ".json" : "my_preset.json",
                     ".json");
}

void begin_open(LabSession& s) {
    const fs::path dir = s.preset_path.empty() ? s.preset_dir : s.preset_path.parent_path();
    open_file_dialog(panels_of(s).file_dialog, FileDialog::Mode::open, FilePurpose::open_preset, "Open preset", dir, "",
                     ".json");
}

void begin_choose_export_folder(LabSession& s) {
    PanelState& p = panels_of(s);
    open_file_dialog(p.file_dialog, FileDialog::Mode::folder, FilePurpose::export_folder, "Export plots to",
                     p.export_dir.empty() ? fs::current_path() : p.export_dir, "", "");
}

bool save_in_place(LabSession& s) {
    if (s.preset_path.empty() || is_shipped_preset(s, s.preset_path)) {
        begin_save_as(s, std::nullopt);
        return false;
    }
    return save_scene_to(s, s.preset_path);
}

bool save_then(LabSession& s, const PendingAction& then) {
    if (s.preset_path.empty() || is_shipped_preset(s, s.preset_path)) {
        begin_save_as(s, then);
        return false;
    }
    return save_scene_to(s, s.preset_path);
}

void draw_file_dialogs(LabSession& s) {
    PanelState& p = panels_of(s);
    const FilePurpose purpose = p.file_dialog.purpose;
    const std::optional<fs::path> chosen = draw_file_dialog(s, p.file_dialog);
    if (!p.file_dialog.visible && !chosen) p.after_save.reset();  // cancelled: the action waits no more
    if (!chosen) return;
    switch (purpose) {
        case FilePurpose::save_preset:
            if (save_scene_to(s, *chosen) && p.after_save) s.perform(*p.after_save);
            p.after_save.reset();
            break;
        case FilePurpose::open_preset: s.request({PendingAction::Kind::open, *chosen}); break;
        case FilePurpose::export_folder:
            p.export_dir = *chosen;
            s.status_message = "Plot exports go to " + chosen->string();
            break;
        case FilePurpose::none: break;
    }
}

}  // namespace pl::ui
