// Plot exports never overwrite a file without asking: write_csv and ask_picture hold back the
// exports whose file exists, and this dialog lists them with Overwrite / Cancel (the exports to
// new files go ahead at once).
#include "ui/lab_ui.hpp"
#include "ui/panel_state.hpp"
#include "ui/sections.hpp"

#include <imgui.h>

#include <fstream>
#include <system_error>

namespace pl::ui {

namespace {

bool file_exists(const std::filesystem::path& file) {
    std::error_code ec;
    return std::filesystem::exists(file, ec);
}

void write_now(LabSession& s, const std::filesystem::path& file, const std::string& csv) {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out << csv;
    out.close();
    if (!out) {
        s.error_popup = "Could not write " + file.string() + " (is the folder writable?)";
        return;
    }
    s.status_message = "Wrote " + file.string();
}

}  // namespace

void write_csv(LabSession& s, const std::filesystem::path& file, const std::string& csv) {
    if (file_exists(file)) panels_of(s).export_question.csv.emplace_back(file, csv);
    else write_now(s, file, csv);
}

void ask_picture(LabSession& s, const std::filesystem::path& file, ImVec2 min, ImVec2 max) {
    PanelState& p = panels_of(s);
    if (file_exists(file)) p.export_question.picture = PendingPicture{2, file, min, max};
    else p.picture = {2, file, min, max};
}

bool export_question_open(const LabSession& s) {
    return s.panels && (!s.panels->export_question.csv.empty() || s.panels->export_question.picture);
}

void draw_export_question(LabSession& s) {
    const char* id = "Overwrite?##exports";
    PendingExports& q = panels_of(s).export_question;
    if (!export_question_open(s)) return;
    if (!ImGui::IsPopupOpen(id)) ImGui::OpenPopup(id);
    ImGui::SetNextWindowPos(ImGui::GetMainViewport()->GetCenter(), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    if (!ImGui::BeginPopupModal(id, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
    ImGui::TextUnformatted("These files exist already:");
    for (const auto& [file, csv] : q.csv) ImGui::BulletText("%s", file.string().c_str());
    if (q.picture) ImGui::BulletText("%s", q.picture->path.string().c_str());
    ImGui::Separator();
    bool done = false;
    if (ImGui::Button("Overwrite")) {
        for (const auto& [file, csv] : q.csv) write_now(s, file, csv);
        // The picture is taken two frames after this dialog closes, so it is not in it.
        if (q.picture) panels_of(s).picture = *q.picture;
        done = true;
    }
    note_item_rect(s, "export.overwrite");
    ImGui::SameLine();
    if (ImGui::Button("Cancel") || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) {
        s.status_message = "Export cancelled: nothing was overwritten";
        done = true;
    }
    note_item_rect(s, "export.cancel");
    ImGui::SetItemDefaultFocus();
    if (done) {
        q = PendingExports{};
        ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
}

}  // namespace pl::ui
