#include "ui/expectations_view.hpp"

#include "ui/plot_history.hpp"
#include "ui/sections.hpp"

#include <imgui.h>

#include <fmt/format.h>

namespace pl::ui {

std::vector<ExpectationResult> live_expectations(const LabSession& s) {
    if (s.scene.expect.empty()) return {};
    std::vector<VariantMetrics> measured;
    if (s.experiment && s.history && s.history->trackers.size() == s.experiment->variant_count())
        for (std::size_t v = 0; v < s.experiment->variant_count(); ++v)
            measured.push_back(metrics_of(s.history->trackers[v], s.experiment->run(v)));
    return check_expectations(s.scene.expect, measured);
}

void draw_expectations(LabSession& s) {
    if (s.scene.expect.empty()) return;
    const std::vector<ExpectationResult> results = live_expectations(s);
    const bool several_variants = s.experiment && s.experiment->variant_count() > 1;
    ImGui::Spacing();
    ImGui::TextDisabled("Expected (preset) -> measured (this run)");
    // Two lines each, the quantity then the numbers: the control panel is narrow.
    for (std::size_t i = 0; i < results.size(); ++i) {
        const ExpectationResult& r = results[i];
        std::string what = to_string(r.expected.quantity);
        if (r.expected.particle > 0) what += fmt::format(", particle {}", r.expected.particle);
        if (several_variants) what += ", " + variant_name(s, r.expected.variant);
        ImGui::BulletText("%s", what.c_str());
        ImGui::Indent();
        ImGui::Text("%.4g +- %.2g  ->", r.expected.value, r.expected.tolerance);
        ImGui::SameLine();
        if (!r.measured) ImGui::TextDisabled("not yet");
        else if (r.met) ImGui::TextColored({0.45f, 0.9f, 0.45f, 1.0f}, "%.4g (within)", *r.measured);
        else ImGui::TextColored({1.0f, 0.7f, 0.3f, 1.0f}, "%.4g (off by %+.2g)", *r.measured, *r.measured - r.expected.value);
        note_item_rect(s, "expect.row" + std::to_string(i));
        ImGui::Unindent();
    }
}

}  // namespace pl::ui
