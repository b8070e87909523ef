#include "app/record_controls.hpp"

#include "ui/sections.hpp"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <cstdio>
#include <string>

namespace pl::app {

namespace {

const ImVec4 rec_red(0.78f, 0.12f, 0.12f, 1.0f);

void report_failure(RecordControl& rec, ui::LabSession& s, const std::string& error) {
    rec.error = error;
    std::fprintf(stderr, "particle-lab: %s\n", error.c_str());
    s.error_popup = error;
}

void stop_recording(RecordControl& rec, ui::LabSession& s) {
    const long frames = rec.recorder.frames();
    const std::filesystem::path file = rec.recorder.settings().file;
    if (const std::string error = rec.recorder.stop(); !error.empty()) {
        report_failure(rec, s, error);
        return;
    }
    rec.last_file = file;
    s.status_message = "Recorded " + std::to_string(frames) + " frames to " + file.string();
}

void start_recording(RecordControl& rec, ui::LabSession& s, const ShellLayout& layout, float dw, float dh, float sx,
                     float sy) {
    const Rect r = record_rect(rec.next.area, layout, dw, dh);
    rec.error.clear();
    if (const std::string error = rec.recorder.start(rec.next, to_pixels(r.x, r.y, r.w, r.h, sx, sy)); !error.empty()) {
        report_failure(rec, s, error);
        return;
    }
    s.status_message = "Recording to " + rec.next.file.string();
}

// The format combo rewrites the file's extension, so the two never disagree.
void format_combo(RecordSettings& next) {
    std::size_t count = 0;
    const VideoFormat* formats = video_formats(count);
    const VideoFormat* current = video_format_for(next.file);
    if (!ImGui::BeginCombo("format", current ? current->name : "(choose)")) return;
    for (std::size_t i = 0; i < count; ++i)
        if (ImGui::Selectable(formats[i].name, current == &formats[i])) next.file.replace_extension(formats[i].extension);
    ImGui::EndCombo();
}

void area_combo(RecordSettings& next) {
    const char* label = "";
    for (const RecordAreaName& a : record_areas())
        if (a.area == next.area) label = a.label;
    if (!ImGui::BeginCombo("area", label)) return;
    for (const RecordAreaName& a : record_areas())
        if (ImGui::Selectable(a.label, a.area == next.area)) next.area = a.area;
    ImGui::EndCombo();
}

void settings_popup(RecordControl& rec, ui::LabSession& s) {
    if (!ImGui::BeginPopup("##record_settings")) return;
    std::string file = rec.next.file.string();
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 24.0f);
    if (ImGui::InputText("file", &file)) rec.next.file = file;
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 10.0f);
    format_combo(rec.next);
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 10.0f);
    area_combo(rec.next);
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 10.0f);
    ImGui::SliderInt("frames per second", &rec.next.fps, min_record_fps, max_record_fps, "%d", ImGuiSliderFlags_AlwaysClamp);
    ImGui::TextDisabled("Each frame advances the simulation by exactly 1/fps s x the time scale,\n"
                        "so the video plays at real speed whatever this display's frame rate.");
    const std::string problem = check_record_file(rec.next.file, "file");
    if (!problem.empty()) ImGui::TextColored(ImVec4(1.0f, 0.75f, 0.3f, 1.0f), "%s", problem.c_str());
    ImGui::BeginDisabled(!problem.empty());
    if (ImGui::Button("Start recording (F9)")) {
        rec.toggle = true;
        ImGui::CloseCurrentPopup();
    }
    ImGui::EndDisabled();
    ui::note_item_rect(s, "record.start");
    ImGui::EndPopup();
}

}  // namespace

void begin_record_frame(RecordControl& rec, ui::LabSession& s, const ShellLayout& layout, float dw, float dh, float sx,
                        float sy) {
    if (!rec.toggle) return;
    rec.toggle = false;
    if (rec.recorder.active()) {
        stop_recording(rec, s);
        return;
    }
    if (rec.next.file.empty()) rec.next.file = default_record_file(s.preset_path.stem().string(), ".mp4");
    start_recording(rec, s, layout, dw, dh, sx, sy);
}

bool end_record_frame(RecordControl& rec, ui::LabSession& s, int fb_w, int fb_h) {
    if (!rec.recorder.active()) return rec.quit_when_done;  // --record: failed to start or finished
    if (const std::string error = rec.recorder.capture(fb_w, fb_h); !error.empty()) {
        report_failure(rec, s, error);
        return rec.quit_when_done;
    }
    if (!rec.recorder.done()) return false;
    stop_recording(rec, s);
    // The next GUI recording gets a fresh name instead of overwriting this one.
    if (!rec.quit_when_done) rec.next.file.clear();
    return rec.quit_when_done;
}

void finish_recording(RecordControl& rec, ui::LabSession& s) {
    if (rec.recorder.active()) stop_recording(rec, s);
}

void draw_record_controls(RecordControl& rec, ui::LabSession& s) {
    if (rec.recorder.active()) {
        // The REC indicator doubles as the stop button.
        ImGui::PushStyleColor(ImGuiCol_Button, rec_red);
        ImGui::PushStyleColor(ImGuiCol_ButtonHovered, ImVec4(0.9f, 0.2f, 0.2f, 1.0f));
        char label[64];
        std::snprintf(label, sizeof label, "REC %.1f s###record", static_cast<double>(rec.recorder.frames()) /
                                                                       rec.recorder.settings().fps);
        if (ImGui::Button(label)) rec.toggle = true;
        ImGui::PopStyleColor(2);
        ui::note_item_rect(s, "record.button");
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("Recording %s: click or F9 to stop", rec.recorder.settings().file.string().c_str());
        return;
    }
    if (ImGui::Button("REC###record")) {
        if (rec.next.file.empty()) rec.next.file = default_record_file(s.preset_path.stem().string(), ".mp4");
        ImGui::OpenPopup("##record_settings");
    }
    ui::note_item_rect(s, "record.button");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Record a video (MP4, WebM) or an animated GIF of the window or part of it (F9 starts and stops)");
    settings_popup(rec, s);
}

}  // namespace pl::app
