#include "ui/field_edit.hpp"

namespace pl::ui {
namespace {

const ImVec4 refused_frame{0.55f, 0.12f, 0.12f, 1.0f};
const ImVec4 refused_text{1.0f, 0.42f, 0.42f, 1.0f};

template <int N>
std::optional<std::array<double, 3>> input_components(FieldEdits& edits, const char* label, std::array<double, 3> value,
                                                      const char* format, const char* help) {
    const ImGuiID id = ImGui::GetID(label);
    const auto refused = edits.refused.find(id);
    const auto editing = edits.editing.find(id);
    std::array<double, 3> shown = editing != edits.editing.end() ? editing->second
                                  : refused != edits.refused.end() ? refused->second.values
                                                                   : value;
    const bool is_refused = refused != edits.refused.end();
    if (is_refused) ImGui::PushStyleColor(ImGuiCol_FrameBg, refused_frame);
    if constexpr (N == 1) ImGui::InputDouble(label, shown.data(), 0.0, 0.0, format);
    else ImGui::InputScalarN(label, ImGuiDataType_Double, shown.data(), N, nullptr, nullptr, format);
    if (is_refused) ImGui::PopStyleColor();
    const bool active = ImGui::IsItemActive();
    const bool committed = ImGui::IsItemDeactivatedAfterEdit();
    if (is_refused && ImGui::IsItemHovered()) {
        ImGui::BeginTooltip();
        ImGui::PushStyleColor(ImGuiCol_Text, refused_text);
        ImGui::TextUnformatted(("Not applied: " + refused->second.message).c_str());
        ImGui::PopStyleColor();
        ImGui::EndTooltip();
    }
    if (active) edits.editing[id] = shown;
    else edits.editing.erase(id);
    if (help) help_marker(help);
    if (is_refused) {
        ImGui::PushID(static_cast<int>(id));
        error_text("Not applied: " + refused->second.message);
        if (ImGui::SmallButton("Revert field")) edits.refused.erase(id);
        ImGui::PopID();
    }
    if (!committed) return std::nullopt;
    edits.last_id = id;
    edits.last_values = shown;
    return shown;
}

}  // namespace

void FieldEdits::resolve(const std::string& message) {
    if (message.empty()) refused.erase(last_id);
    else refused[last_id] = {last_values, message};
}

std::optional<double> input_number(FieldEdits& edits, const char* label, double value, const char* format, const char* help) {
    const auto r = input_components<1>(edits, label, {value, 0.0, 0.0}, format, help);
    if (!r) return std::nullopt;
    return (*r)[0];
}

std::optional<Vec3> input_vec3(FieldEdits& edits, const char* label, const Vec3& value, const char* format, const char* help) {
    const auto r = input_components<3>(edits, label, {value.x, value.y, value.z}, format, help);
    if (!r) return std::nullopt;
    return Vec3((*r)[0], (*r)[1], (*r)[2]);
}

void help_marker(const char* text) {
    ImGui::SameLine();
    ImGui::TextDisabled("(?)");
    if (ImGui::IsItemHovered()) {
        ImGui::BeginTooltip();
        ImGui::PushTextWrapPos(ImGui::GetFontSize() * 30.0f);
        ImGui::TextUnformatted(text);
        ImGui::PopTextWrapPos();
        ImGui::EndTooltip();
    }
}

void error_text(const std::string& message) {
    ImGui::PushStyleColor(ImGuiCol_Text, refused_text);
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextUnformatted(message.c_str());
    ImGui::PopTextWrapPos();
    ImGui::PopStyleColor();
}

}  // namespace pl::ui
