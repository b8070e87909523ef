// A small file dialog drawn in ImGui: the folder's listing (folders first), parent and child
// navigation, a filename field and a filter by extension. It opens, saves (asking before it
// overwrites a file: Overwrite / Cancel) and picks folders. Keyboard: the filename field has
// the keyboard when the dialog opens; Enter confirms (a folder's name, "..", or a path to a
// folder navigates there instead), Esc cancels, Backspace in an empty field goes to the parent.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace pl::ui {

struct LabSession;

struct FolderEntry {
    std::string name;
    bool is_dir = false;
};

// The folder's entries: sub-folders, then the files ending in `extension` (all files when
// empty), each group sorted by name; hidden entries (".name") left out. Empty when unreadable.
std::vector<FolderEntry> list_folder(const std::filesystem::path& dir, const std::string& extension);

// Why `name` cannot be a file name here (empty: it can): letters, digits, space, '-', '_', '.';
// no path separators; at most 100 characters.
std::string bad_file_name(const std::string& name);

// What the dialog does once a path is chosen; the caller reads it with the chosen path.
enum class FilePurpose { none, open_preset, save_preset, export_folder };

struct FileDialog {
    enum class Mode { open, save, folder };
    bool visible = false;
    Mode mode = Mode::open;
    FilePurpose purpose = FilePurpose::none;
    std::string title;
    std::filesystem::path dir;
    std::string filename;
    std::string extension;  // ".json"; empty: every file
    std::vector<FolderEntry> entries;
    bool listed = false;          // entries are those of `dir`
    bool focus_name = false;      // the next frame puts the keyboard in the filename field
    bool just_opened = false;     // the key that opened the dialog must not confirm it
    std::optional<std::filesystem::path> overwrite;  // asked: this file exists
    std::string error;            // shown under the field
};

// Shows the dialog in `dir` (created when missing, for a save), with `filename` filled in.
void open_file_dialog(FileDialog& d, FileDialog::Mode mode, FilePurpose purpose, std::string title,
                      std::filesystem::path dir, std::string filename, std::string extension);

// Draws the dialog when visible; returns the chosen path (a file, or for Mode::folder a folder)
// once, on the frame it is confirmed, and hides the dialog. `s` receives the widget rectangles
// the GUI tests click ("file_dialog.ok", "file_dialog.cancel", "file_dialog.overwrite",
// "file_dialog.keep").
std::optional<std::filesystem::path> draw_file_dialog(LabSession& s, FileDialog& d);

}  // namespace pl::ui
