// The one question before unsaved edits are lost: whatever would drop the scene (Ctrl+O, Load,
// Revert, Ctrl+Q, closing the window) waits in LabSession::pending until it is answered here.
// Save saves first (not offered for Revert, which would only reload what was just saved), Discard
// goes ahead, Cancel keeps the edit.
#include "ui/lab_ui.hpp"
#include "ui/sections.hpp"

#include <imgui.h>

#include <string>

namespace pl::ui {

namespace {

struct ActionWords {
    const char* save;     // the Save button; null: not offered
    const char* discard;  // the Discard button
    const char* what;     // what would happen, after "unsaved changes; "
};

ActionWords words_of(const PendingAction& a) {
    switch (a.kind) {
        case PendingAction::Kind::quit: return {"Save and quit", "Quit without saving", "quitting loses them."};
        case PendingAction::Kind::open: return {"Save and open", "Discard and open", "opening another preset loses them:"};
        case PendingAction::Kind::revert: return {nullptr, "Discard and revert", "reverting reloads the file:"};
    }
    return {nullptr, "Discard", ""};
}

}  // namespace

void draw_unsaved_prompt(LabSession& s) {
    const char* id = "Unsaved changes##prompt";
    const bool open = ImGui::IsPopupOpen(id);
    // An error dialog goes first; the question comes back once it is read.
    if (s.pending && !open && s.error_popup.empty()) ImGui::OpenPopup(id);
    ImGui::SetNextWindowPos(ImGui::GetMainViewport()->GetCenter(), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    if (!ImGui::BeginPopupModal(id, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
    if (!s.pending) {  // answered elsewhere (Esc)
        ImGui::CloseCurrentPopup();
        ImGui::EndPopup();
        return;
    }
    const PendingAction action = *s.pending;
    const ActionWords w = words_of(action);
    ImGui::Text("\"%s\" has unsaved changes; %s", s.scene.name.c_str(), w.what);
    if (action.kind != PendingAction::Kind::quit) ImGui::TextUnformatted(action.file.string().c_str());
    ImGui::TextDisabled("%s", s.preset_path.empty() ? "The scene was never saved." : ("Saved to: " + s.preset_path.string()).c_str());
    ImGui::Separator();
    if (w.save) {
        // A failed save drops the question: the edit stays, and the error dialog says why. A
        // shipped preset or a scene without a file asks where first (Save As), then goes ahead.
        if (ImGui::Button(w.save)) {
            if (save_then(s, action)) s.perform(action);
            else s.pending.reset();
        }
        note_item_rect(s, "unsaved.save");
        ImGui::SameLine();
    }
    if (ImGui::Button(w.discard)) s.perform(action);
    note_item_rect(s, "unsaved.discard");
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) s.pending.reset();
    note_item_rect(s, "unsaved.cancel");
    ImGui::SetItemDefaultFocus();
    if (!s.pending) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
}

}  // namespace pl::ui
