// The panels the shell lays out: control column, analysis tabs, status bar and popups.
// (The plots region is in plots_panel.cpp, the recording in frame_recorder.cpp.)
#include "ui/lab_ui.hpp"

#include "ui/panel_state.hpp"
#include "ui/pinned_runs.hpp"
#include "ui/sections.hpp"
#include "ui/warning_risk.hpp"

#include <imgui.h>

#include <string>
#include <vector>

namespace pl::ui {

PanelState& panels_of(LabSession& s) {
    if (!s.panels) s.panels = std::make_shared<PanelState>();
    return *s.panels;
}

std::string variant_name(const LabSession& s, std::size_t v) {
    if (s.experiment && v < s.experiment->variant_count()) {
        const std::string& label = s.experiment->run(v).model().label;
        if (!label.empty()) return label;
    }
    if (s.experiment && s.experiment->variant_count() == 1) return "scene";
    return "variant " + std::to_string(v);
}

void note_item_rect(LabSession& s, const std::string& name) {
    if (!ImGui::IsItemVisible()) return;
    const ImVec2 lo = ImGui::GetItemRectMin(), hi = ImGui::GetItemRectMax();
    s.widget_rects[name] = {lo.x, lo.y, hi.x - lo.x, hi.y - lo.y};
}

struct WarningTally {
    struct Variant {
        const Simulation* sim = nullptr;
        std::size_t read = 0;  // warnings counted
        Warning first{};       // the first of them: a reset or a new run starts the list over
        std::size_t at_risk = 0, notes = 0;
    };
    std::vector<Variant> variants;
};

namespace {

bool same_warning(const Warning& a, const Warning& b) {
    return a.kind == b.kind && a.particle == b.particle && a.t == b.t && a.value == b.value;
}

// Counts the warnings each variant raised since the last call; the engine only appends to a
// run's list until a reset or a new experiment, which the first entry and the run's address tell.
const WarningTally& tally_warnings(const LabSession& s) {
    if (!s.warning_tally) s.warning_tally = std::make_shared<WarningTally>();
    WarningTally& tally = *s.warning_tally;
    const std::size_t count = s.experiment ? s.experiment->variant_count() : 0;
    tally.variants.resize(count);
    for (std::size_t v = 0; v < count; ++v) {
        const Simulation& sim = s.experiment->run(v);
        const std::vector<Warning>& list = sim.warnings();
        WarningTally::Variant& t = tally.variants[v];
        if (t.sim != &sim || list.size() < t.read || (t.read > 0 && !same_warning(list.front(), t.first))) t = {&sim};
        for (; t.read < list.size(); ++t.read) (puts_number_at_risk(list[t.read], sim) ? t.at_risk : t.notes) += 1;
        if (!list.empty()) t.first = list.front();
    }
    return tally;
}

std::size_t count_warnings(const LabSession& s, bool at_risk) {
    std::size_t n = 0;
    for (const WarningTally::Variant& v : tally_warnings(s).variants) n += at_risk ? v.at_risk : v.notes;
    return n;
}

}  // namespace

std::size_t warning_count(const LabSession& s) { return count_warnings(s, true); }
std::size_t note_count(const LabSession& s) { return count_warnings(s, false); }

void draw_control_panel(LabSession& s) {
    ImGui::PushItemWidth(ImGui::GetContentRegionAvail().x * 0.5f);
    const std::string preset_header = std::string("Preset") + (s.dirty ? " *" : "") + "###preset";
    if (panels_of(s).focus_open_path) ImGui::SetNextItemOpen(true);  // Ctrl+O needs its field on screen
    if (ImGui::CollapsingHeader(preset_header.c_str(), ImGuiTreeNodeFlags_DefaultOpen)) draw_preset_section(s);
    if (ImGui::CollapsingHeader("About this experiment", ImGuiTreeNodeFlags_DefaultOpen)) draw_about_section(s);
    const std::size_t pinned = pins_if_any(s) ? pins_if_any(s)->runs.size() : 0;
    const std::string runs_header = "Runs (" + std::to_string(pinned) + " pinned)###runs";
    if (ImGui::CollapsingHeader(runs_header.c_str(), ImGuiTreeNodeFlags_DefaultOpen)) draw_runs_section(s);
    if (ImGui::CollapsingHeader("Time", ImGuiTreeNodeFlags_DefaultOpen)) draw_time_section(s);
    if (ImGui::CollapsingHeader("Launch", ImGuiTreeNodeFlags_DefaultOpen)) draw_launch_section(s);
    if (ImGui::CollapsingHeader("Scene")) draw_scene_section(s);
    const std::string variants_header =
        "Variants (" + std::to_string(s.scene.variants.empty() ? 1 : s.scene.variants.size()) + ")###variants";
    if (ImGui::CollapsingHeader(variants_header.c_str())) draw_variants_section(s);
    if (ImGui::CollapsingHeader("Inspector", ImGuiTreeNodeFlags_DefaultOpen)) draw_inspector_section(s);
    ImGui::PopItemWidth();
}

void draw_analysis_panel(LabSession& s) {
    if (!s.experiment) return;
    if (!ImGui::BeginTabBar("##analysis")) return;
    if (ImGui::BeginTabItem("Compare")) {
        draw_compare_tab(s);
        ImGui::EndTabItem();
    }
    if (ImGui::BeginTabItem("Events")) {
        draw_events_tab(s);
        ImGui::EndTabItem();
    }
    if (ImGui::BeginTabItem("Energy ledger")) {
        draw_ledger_tab(s);
        ImGui::EndTabItem();
    }
    if (ImGui::BeginTabItem("Accuracy")) {
        draw_accuracy_tab(s);
        ImGui::EndTabItem();
    }
    if (ImGui::BeginTabItem("Stability")) {
        draw_stability_tab(s);
        ImGui::EndTabItem();
    }
    const bool sweep_open = ImGui::BeginTabItem("Sweep");
    note_item_rect(s, "tab.sweep");
    if (sweep_open) {
        draw_sweep_tab(s);
        ImGui::EndTabItem();
    }
    const bool advise_open = ImGui::BeginTabItem("Advise");
    note_item_rect(s, "tab.advise");
    if (advise_open) {
        draw_advise_tab(s);
        ImGui::EndTabItem();
    }
    const std::size_t warnings = warning_count(s);
    const std::string warnings_tab = warnings ? "Warnings (" + std::to_string(warnings) + ")###warnings" : "Warnings###warnings";
    if (warnings) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.75f, 0.3f, 1.0f));
    const bool open = ImGui::BeginTabItem(warnings_tab.c_str());
    note_item_rect(s, "tab.warnings");
    if (warnings) ImGui::PopStyleColor();
    if (open) {
        draw_warnings_tab(s);
        ImGui::EndTabItem();
    }
    ImGui::EndTabBar();
}

void draw_status_bar(LabSession& s) {
    const ImVec4 warn{1.0f, 0.75f, 0.3f, 1.0f};
    const double t = s.experiment ? s.experiment->time() : 0.0;
    auto separator = [] {
        ImGui::SameLine();
        ImGui::TextDisabled("|");
        ImGui::SameLine();
    };
    ImGui::Text("t = %.3f s", t);
    separator();
    if (s.paused) ImGui::TextUnformatted("paused");
    else ImGui::Text("%.2fx real time", s.frame.real_time_factor);
    separator();
    ImGui::Text("%llu substeps/frame", static_cast<unsigned long long>(s.frame.substeps));
    separator();
    ImGui::Text("physics %.2f ms, render %.2f ms per frame", s.frame.physics_ms, s.frame.render_ms);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Physics runs in its own thread; this is its stepping time between two frames.\n"
                          "Render is the frame's own work: panels, the 3D view and presenting it.");
    separator();
    ImGui::Text("%.0f FPS", s.frame.fps);
    const std::size_t warnings = warning_count(s);
    separator();
    if (warnings) ImGui::TextColored(warn, "%zu warning%s", warnings, warnings == 1 ? "" : "s");
    else ImGui::TextDisabled("no warnings");
    if (s.frame.behind) {
        separator();
        ImGui::TextColored(warn, "behind real time");
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("Physics cannot keep up at this time scale: steps were dropped this frame.\n"
                              "The trajectory is unaffected; only the pace is slower than asked.");
    }
    if (s.dirty) {
        separator();
        ImGui::TextColored(warn, "* unsaved");
    }
    if (!s.status_message.empty()) {
        separator();
        ImGui::TextDisabled("%s", s.status_message.c_str());
    }
}

namespace {

void error_modal(LabSession& s) {
    const bool open = ImGui::IsPopupOpen("Error##modal");
    if (!s.error_popup.empty() && !open) ImGui::OpenPopup("Error##modal");
    const ImVec2 centre = ImGui::GetMainViewport()->GetCenter();
    ImGui::SetNextWindowPos(centre, ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSizeConstraints(ImVec2(360, 0), ImVec2(ImGui::GetMainViewport()->Size.x * 0.8f, ImGui::GetMainViewport()->Size.y * 0.8f));
    if (!ImGui::BeginPopupModal("Error##modal", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
    if (s.error_popup.empty()) {  // closed from elsewhere (Esc)
        ImGui::CloseCurrentPopup();
        ImGui::EndPopup();
        return;
    }
    ImGui::PushTextWrapPos(ImGui::GetMainViewport()->Size.x * 0.7f);
    ImGui::TextUnformatted(s.error_popup.c_str());
    ImGui::PopTextWrapPos();
    ImGui::Separator();
    // Enter counts from the dialog's second frame: the Enter that loaded a bad file from the
    // path field must not dismiss its own error unread.
    if (ImGui::Button("OK", ImVec2(120, 0)) || (open && ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter)))) {
        s.error_popup.clear();
        ImGui::CloseCurrentPopup();
    }
    ImGui::SetItemDefaultFocus();
    ImGui::EndPopup();
}

void help_overlay(LabSession& s) {
    if (!s.show_help) return;
    const ImGuiViewport* vp = ImGui::GetMainViewport();
    ImGui::SetNextWindowPos(vp->GetCenter(), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowBgAlpha(0.92f);
    if (!ImGui::Begin("Keys and mouse (F1 or H to close)", &s.show_help,
                      ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings)) {
        ImGui::End();
        return;
    }
    static const char* rows[][2] = {
        {"Space", "play / pause"},
        {"N", "one step (pauses)"},
        {"R", "reset to the preset's initial state"},
        {"L", "launch particle 0 again with the Launch panel's velocity"},
        {"P", "pin this run: it stays beside the live run (plots, 3D view, Compare tab)"},
        {"M", "measuring tool: click two points (a ball or a trail sample) to read the distance\n"
              "and the time between them; Esc clears"},
        {"W A S D", "move the camera forward / left / back / right"},
        {"Q E", "move the camera down / up"},
        {"left drag", "orbit the camera around the room"},
        {"right or middle drag", "pan (or Shift + left drag)"},
        {"mouse wheel", "zoom the 3D view; over a plot: zoom time"},
        {"click a particle", "select it for the inspector and the plots"},
        {"Ctrl + left drag", "aim a launch from a particle (elsewhere: the selected one) in the plane facing\n"
                             "you; the arrow is its straight path in the time shown. Release launches,\n"
                             "Esc or right-click cancels"},
        {"1 2 3 (shift: other side)", "look along x / y / z"},
        {"0", "reset the view"},
        {"F", "focus the selected particle"},
        {"F9", "start / stop recording a video (file, format, area: the REC button)"},
        {"F1 or H", "this help"},
        {"Esc", "close dialogs, cancel an aim, clear a measurement"},
        {"Ctrl+S", "save the preset over its file (previous kept as .bak); a shipped preset is\n"
                   "read-only: Ctrl+S saves a copy into your presets folder (a file dialog asks the name)"},
        {"Ctrl+O", "type a preset's path, Enter opens it"},
        {"Ctrl+Q", "quit (asks if there are unsaved changes)"},
        {"plots: drag", "scroll back in time (stops following)"},
        {"plots: double-click", "follow the latest samples again"},
        {"plots: legend click", "hide / show a series"},
        {"plots: right-click", "export CSV or PNG, fit options"},
    };
    if (ImGui::BeginTable("keys", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit)) {
        for (const auto& r : rows) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextColored(ImVec4(1.0f, 0.85f, 0.45f, 1.0f), "%s", r[0]);
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(r[1]);
        }
        ImGui::EndTable();
    }
    if (ImGui::Button("Close")) s.show_help = false;
    ImGui::End();
}

}  // namespace

void draw_popups(LabSession& s) {
    help_overlay(s);
    draw_unsaved_prompt(s);
    draw_file_dialogs(s);
    draw_export_question(s);
    error_modal(s);
}

}  // namespace pl::ui
