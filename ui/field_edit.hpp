// Number inputs that hand the committed value back instead of writing it, so the caller can
// check the whole edit before applying it. A refused value stays in the field, framed red, with
// the reason under it and in a tooltip, until it is corrected or reverted; the scene is never
// changed half-way.
#pragma once

#include "physics/model/scene.hpp"

#include <imgui.h>

#include <array>
#include <optional>
#include <string>
#include <unordered_map>

namespace pl::ui {

struct FieldEdits {
    struct Refused {
        std::array<double, 3> values{};
        std::string message;
    };
    std::unordered_map<ImGuiID, std::array<double, 3>> editing;  // value being typed, per field
    std::unordered_map<ImGuiID, Refused> refused;
    // The last committed input (for resolve()).
    ImGuiID last_id = 0;
    std::array<double, 3> last_values{};

    // Accepts (empty message) or refuses the value the last input committed.
    void resolve(const std::string& message);
    void clear() {
        editing.clear();
        refused.clear();
    }
};

// `help`, when given, is a "(?)" tooltip beside the field.
std::optional<double> input_number(FieldEdits& edits, const char* label, double value, const char* format = "%.6g",
                                   const char* help = nullptr);
std::optional<Vec3> input_vec3(FieldEdits& edits, const char* label, const Vec3& value, const char* format = "%.4g",
                               const char* help = nullptr);

// "(?)" on the same line, with a tooltip.
void help_marker(const char* text);

// Red text for a rule the current state breaks (used beside inputs, and by the refusal).
void error_text(const std::string& message);

}  // namespace pl::ui
