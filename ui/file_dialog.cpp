#include "ui/file_dialog.hpp"

#include "ui/sections.hpp"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cctype>
#include <system_error>

namespace pl::ui {

namespace fs = std::filesystem;

std::vector<FolderEntry> list_folder(const fs::path& dir, const std::string& extension) {
    std::vector<FolderEntry> folders, files;
    std::error_code ec;
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (name.empty() || name[0] == '.') continue;
        std::error_code type_ec;
        if (it->is_directory(type_ec)) folders.push_back({name, true});
        else if (extension.empty() || it->path().extension() == extension) files.push_back({name, false});
    }
    auto by_name = [](const FolderEntry& a, const FolderEntry& b) { return a.name < b.name; };
    std::sort(folders.begin(), folders.end(), by_name);
    std::sort(files.begin(), files.end(), by_name);
    folders.insert(folders.end(), files.begin(), files.end());
    return folders;
}

std::string bad_file_name(const std::string& name) {
    if (name.empty()) return "type a name first";
    if (name.size() > 100) return "name: at most 100 characters";
    if (name == "." || name == "..") return "name: not a file name";
    for (char c : name)
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.' || c == ' '))
            return std::string("name: only letters, digits, space, '-', '_' and '.' (found '") + c + "')";
    return {};
}

void open_file_dialog(FileDialog& d, FileDialog::Mode mode, FilePurpose purpose, std::string title, fs::path dir,
                      std::string filename, std::string extension) {
    std::error_code ec;
    if (mode == FileDialog::Mode::save) fs::create_directories(dir, ec);
    if (dir.empty() || !fs::is_directory(dir, ec)) dir = fs::current_path(ec);
    d = FileDialog{};
    d.visible = true;
    d.mode = mode;
    d.purpose = purpose;
    d.title = std::move(title);
    d.dir = fs::weakly_canonical(dir, ec);
    if (ec) d.dir = dir;
    d.filename = std::move(filename);
    d.extension = std::move(extension);
    d.focus_name = true;
    d.just_opened = true;
}

namespace {

void go_to(FileDialog& d, const fs::path& dir) {
    std::error_code ec;
    const fs::path canonical = fs::weakly_canonical(dir, ec);
    d.dir = ec ? dir : canonical;
    d.listed = false;
    d.error.clear();
    d.focus_name = true;
}

// What the filename field asks for on Enter: a folder to go to, or the chosen path (nullopt and
// d.error set when neither).
std::optional<fs::path> resolve(FileDialog& d) {
    std::error_code ec;
    const fs::path typed = d.filename;
    const fs::path full = typed.is_absolute() ? typed : d.dir / typed;
    if (d.filename == ".." || (!d.filename.empty() && fs::is_directory(full, ec))) {
        go_to(d, full);
        d.filename.clear();
        return std::nullopt;
    }
    if (d.mode == FileDialog::Mode::folder) {
        if (d.filename.empty()) return d.dir;
        d.error = "no such folder: " + full.string();
        return std::nullopt;
    }
    if (typed.has_parent_path()) {  // a path to a file: its folder must exist
        if (!fs::is_directory(full.parent_path(), ec)) {
            d.error = "no such folder: " + full.parent_path().string();
            return std::nullopt;
        }
        go_to(d, full.parent_path());
        d.filename = full.filename().string();
    }
    if (const std::string why = bad_file_name(d.filename); !why.empty()) {
        d.error = why;
        return std::nullopt;
    }
    fs::path chosen = d.dir / d.filename;
    if (d.mode == FileDialog::Mode::save && !d.extension.empty() && chosen.extension() != d.extension)
        chosen += d.extension;
    if (d.mode == FileDialog::Mode::open && !fs::is_regular_file(chosen, ec)) {
        d.error = "no such file: " + chosen.string();
        return std::nullopt;
    }
    return chosen;
}

// The listing; a double-click on a file confirms it (set in `confirm`).
void draw_listing(FileDialog& d, bool& confirm) {
    if (!d.listed) {
        d.entries = list_folder(d.dir, d.extension);
        if (d.mode == FileDialog::Mode::folder)
            d.entries.erase(std::remove_if(d.entries.begin(), d.entries.end(), [](const FolderEntry& e) { return !e.is_dir; }),
                            d.entries.end());
        d.listed = true;
    }
    const float h = ImGui::GetTextLineHeightWithSpacing() * 14.0f;
    if (!ImGui::BeginChild("##listing", ImVec2(ImGui::GetFontSize() * 36.0f, h), true)) {
        ImGui::EndChild();
        return;
    }
    std::optional<fs::path> next;
    if (d.dir.has_parent_path() && d.dir != d.dir.root_path() &&
        ImGui::Selectable("../", false, ImGuiSelectableFlags_AllowDoubleClick) && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left))
        next = d.dir.parent_path();
    for (const FolderEntry& e : d.entries) {
        const bool selected = !e.is_dir && e.name == d.filename;
        if (!ImGui::Selectable(e.is_dir ? (e.name + "/").c_str() : e.name.c_str(), selected, ImGuiSelectableFlags_AllowDoubleClick))
            continue;
        const bool twice = ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left);
        if (e.is_dir && twice) next = d.dir / e.name;
        if (!e.is_dir) {
            d.filename = e.name;
            confirm = confirm || twice;
        }
    }
    if (d.entries.empty()) ImGui::TextDisabled(d.mode == FileDialog::Mode::folder ? "(no folders)" : "(no matching files)");
    ImGui::EndChild();
    if (next) go_to(d, *next);
}

const char* confirm_word(FileDialog::Mode m) {
    switch (m) {
        case FileDialog::Mode::open: return "Open";
        case FileDialog::Mode::save: return "Save";
        case FileDialog::Mode::folder: return "Choose this folder";
    }
    return "OK";
}

// The overwrite question, in place of the listing; returns the path once Overwrite is pressed.
std::optional<fs::path> draw_overwrite(LabSession& s, FileDialog& d) {
    ImGui::Text("%s already exists.", d.overwrite->filename().string().c_str());
    ImGui::TextDisabled("%s", d.overwrite->string().c_str());
    ImGui::TextUnformatted("Replace it? (the previous file is kept as .bak)");
    ImGui::Separator();
    std::optional<fs::path> chosen;
    if (ImGui::Button("Overwrite")) chosen = d.overwrite;
    note_item_rect(s, "file_dialog.overwrite");
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) {
        d.overwrite.reset();
        d.focus_name = true;
    }
    note_item_rect(s, "file_dialog.keep");
    ImGui::SetItemDefaultFocus();
    return chosen;
}

}  // namespace

std::optional<fs::path> draw_file_dialog(LabSession& s, FileDialog& d) {
    if (!d.visible) return std::nullopt;
    const std::string id = d.title + "##file_dialog";
    if (!ImGui::IsPopupOpen(id.c_str())) ImGui::OpenPopup(id.c_str());
    ImGui::SetNextWindowPos(ImGui::GetMainViewport()->GetCenter(), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    if (!ImGui::BeginPopupModal(id.c_str(), nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return std::nullopt;
    std::optional<fs::path> chosen;
    bool cancel = ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape));
    if (d.overwrite) {
        chosen = draw_overwrite(s, d);
    } else {
        ImGui::TextDisabled("folder");
        ImGui::SameLine();
        ImGui::TextUnformatted(d.dir.string().c_str());
        bool confirm = false;
        draw_listing(d, confirm);
        const bool back = d.filename.empty() && ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Backspace));
        if (d.focus_name) {
            ImGui::SetKeyboardFocusHere();
            d.focus_name = false;
        }
        ImGui::SetNextItemWidth(ImGui::GetFontSize() * 28.0f);
        const char* hint = d.mode == FileDialog::Mode::folder ? "sub-folder or path (empty: this folder)" : "file name";
        if (ImGui::InputTextWithHint("##name", hint, &d.filename, ImGuiInputTextFlags_EnterReturnsTrue) && !d.just_opened)
            confirm = true;
        if (back && ImGui::IsItemActive() && d.dir.has_parent_path()) go_to(d, d.dir.parent_path());
        if (!d.extension.empty()) {
            ImGui::SameLine();
            ImGui::TextDisabled("*%s", d.extension.c_str());
        }
        if (!d.error.empty()) ImGui::TextColored({1.0f, 0.42f, 0.42f, 1.0f}, "%s", d.error.c_str());
        if (ImGui::Button(confirm_word(d.mode))) confirm = true;
        note_item_rect(s, "file_dialog.ok");
        ImGui::SameLine();
        if (ImGui::Button("Cancel")) cancel = true;
        note_item_rect(s, "file_dialog.cancel");
        d.just_opened = false;
        if (confirm && !cancel) {
            std::error_code ec;
            chosen = resolve(d);
            if (chosen && d.mode == FileDialog::Mode::save && fs::exists(*chosen, ec)) {
                d.overwrite = chosen;
                chosen.reset();
            }
        }
    }
    if (chosen || cancel) {
        d.visible = false;
        d.overwrite.reset();
        ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
    if (cancel) d.purpose = FilePurpose::none;
    return chosen;
}

}  // namespace pl::ui
