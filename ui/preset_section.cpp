#include "io/preset_io.hpp"
#include "ui/lab_ui.hpp"
#include "ui/panel_state.hpp"
#include "ui/sections.hpp"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <system_error>

namespace pl::ui {
namespace {

void scan_folder(const std::filesystem::path& dir, bool shipped, std::vector<PresetEntry>& out) {
    std::error_code ec;
    if (dir.empty() || !std::filesystem::is_directory(dir, ec)) return;
    std::vector<PresetEntry> found;
    for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
        if (entry.path().extension() != ".json" || !entry.is_regular_file(ec)) continue;
        found.push_back({entry.path(), entry.path().stem().string(), shipped});
    }
    std::sort(found.begin(), found.end(), [](const PresetEntry& a, const PresetEntry& b) { return a.name < b.name; });
    out.insert(out.end(), found.begin(), found.end());
}

void rescan(LabSession& s, PanelState& p) {
    p.presets.clear();
    // Without the shipped folder, the folder of the preset that opened is the next best thing.
    scan_folder(!s.preset_dir.empty() ? s.preset_dir : s.preset_path.parent_path(), !s.preset_dir.empty(), p.presets);
    scan_folder(user_preset_dir(), false, p.presets);
    p.presets_scanned = true;
    p.preset_choice = -1;
    for (std::size_t i = 0; i < p.presets.size(); ++i) {
        std::error_code ec;
        if (!s.preset_path.empty() && std::filesystem::equivalent(p.presets[i].path, s.preset_path, ec))
            p.preset_choice = static_cast<int>(i);
    }
}

}  // namespace

void focus_open_path(LabSession& s) { panels_of(s).focus_open_path = true; }

void draw_preset_section(LabSession& s) {
    PanelState& p = panels_of(s);
    if (!p.presets_scanned) rescan(s, p);

    ImGui::Text("%s%s", s.scene.name.c_str(), s.dirty ? " *" : "");
    if (s.dirty && ImGui::IsItemHovered()) ImGui::SetTooltip("Unsaved changes");
    ImGui::TextDisabled("%s", s.preset_path.empty() ? "(not saved yet)" : s.preset_path.filename().string().c_str());
    if (ImGui::IsItemHovered() && !s.preset_path.empty()) ImGui::SetTooltip("%s", s.preset_path.string().c_str());

    const float list_h = ImGui::GetTextLineHeightWithSpacing() * 7.5f;
    if (ImGui::BeginListBox("##presets", ImVec2(-1.0f, list_h))) {
        bool user_header = false;
        for (std::size_t i = 0; i < p.presets.size(); ++i) {
            const PresetEntry& e = p.presets[i];
            if (i == 0 && e.shipped) ImGui::TextDisabled("shipped (read-only)");
            if (!e.shipped && !user_header) {
                ImGui::TextDisabled("your presets");
                user_header = true;
            }
            const bool selected = p.preset_choice == static_cast<int>(i);
            if (ImGui::Selectable((e.name + "##" + std::to_string(i)).c_str(), selected, ImGuiSelectableFlags_AllowDoubleClick)) {
                p.preset_choice = static_cast<int>(i);
                if (ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) s.request({PendingAction::Kind::open, e.path});
            }
            note_item_rect(s, "preset." + e.name);
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s\n(double-click to load)", e.path.string().c_str());
        }
        if (p.presets.empty()) ImGui::TextDisabled("no presets found");
        ImGui::EndListBox();
    }
    const bool chosen = p.preset_choice >= 0 && p.preset_choice < static_cast<int>(p.presets.size());
    ImGui::BeginDisabled(!chosen);
    if (ImGui::Button("Load") && chosen)
        s.request({PendingAction::Kind::open, p.presets[static_cast<std::size_t>(p.preset_choice)].path});
    note_item_rect(s, "preset.load");
    ImGui::EndDisabled();
    ImGui::SameLine();
    // Save on a shipped preset (read-only) or a scene without a file asks where, as Save as does.
    if (ImGui::Button("Save")) save_in_place(s);
    note_item_rect(s, "preset.save");
    if (ImGui::IsItemHovered() && is_shipped_preset(s, s.preset_path))
        ImGui::SetTooltip("Shipped presets are read-only: Save writes a copy into %s", user_preset_dir().string().c_str());
    ImGui::SameLine();
    if (ImGui::Button("Save as...")) begin_save_as(s, std::nullopt);
    note_item_rect(s, "preset.save_as");
    ImGui::SameLine();
    ImGui::BeginDisabled(s.preset_path.empty());
    if (ImGui::Button("Revert")) s.request({PendingAction::Kind::revert, s.preset_path});
    note_item_rect(s, "preset.revert");
    ImGui::EndDisabled();
    ImGui::SameLine();
    if (ImGui::Button("Rescan")) rescan(s, p);
    if (ImGui::Button("Open...")) begin_open(s);
    note_item_rect(s, "preset.open_dialog");
    ImGui::SameLine();
    ImGui::TextDisabled("your presets: %s", user_preset_dir().string().c_str());

    ImGui::SetNextItemWidth(-ImGui::CalcTextSize("Open").x - ImGui::GetStyle().ItemSpacing.x - ImGui::GetStyle().FramePadding.x * 2);
    if (p.focus_open_path) {
        ImGui::SetWindowFocus();
        ImGui::SetKeyboardFocusHere();
        p.focus_open_path = false;
    }
    const bool enter = ImGui::InputTextWithHint("##open", "path/to/preset.json", &p.open_path,
                                               ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_AutoSelectAll);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Ctrl+O: type a preset's path, Enter opens it");
    ImGui::SameLine();
    if ((ImGui::Button("Open") || enter) && !p.open_path.empty()) s.request({PendingAction::Kind::open, p.open_path});
}

}  // namespace pl::ui
