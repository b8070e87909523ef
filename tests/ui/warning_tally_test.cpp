// The status bar's warning and note counts are kept incrementally (LabSession::warning_tally):
// only warnings raised since the last count are read. They must always equal a full count over
// every warning, as the run raises more, after a reset and after a new experiment.
#include "io/preset_io.hpp"
#include "ui/sections.hpp"
#include "ui/warning_risk.hpp"

#include <gtest/gtest.h>

namespace pl::ui {
namespace {

std::pair<std::size_t, std::size_t> full_count(const LabSession& s) {
    std::size_t at_risk = 0, notes = 0;
    for (const Simulation& sim : s.experiment->runs())
        for (const Warning& w : sim.warnings()) (puts_number_at_risk(w, sim) ? at_risk : notes) += 1;
    return {at_risk, notes};
}

void expect_counts_match(const LabSession& s, const char* when) {
    const auto [at_risk, notes] = full_count(s);
    EXPECT_EQ(warning_count(s), at_risk) << when;
    EXPECT_EQ(note_count(s), notes) << when;
}

TEST(WarningTally, IncrementalCountsEqualAFullCount) {
    // drag_models: the Stokes variant's warnings are at risk, the constant-Cd ones are notes.
    const LoadResult preset = load_preset(std::filesystem::path(PL_SOURCE_DIR) / "presets" / "drag_models.json");
    ASSERT_TRUE(preset.ok()) << preset.error_text();
    LabSession s;
    ASSERT_EQ(s.open_preset(*preset.scene, "drag_models.json"), "");
    expect_counts_match(s, "at the start");
    std::size_t seen = 0;
    for (int k = 0; k < 40; ++k) {
        s.experiment->step_base(50);
        expect_counts_match(s, "while running");
        seen = std::max(seen, warning_count(s) + note_count(s));
    }
    ASSERT_GT(seen, 0u) << "the scene raised no warning: the test shows nothing";
    s.experiment->reset();
    expect_counts_match(s, "after a reset");
    s.experiment->step_base(700);
    expect_counts_match(s, "running again after the reset");
    ASSERT_EQ(s.apply_scene(*preset.scene), "");
    expect_counts_match(s, "on a new experiment");
}

}  // namespace
}  // namespace pl::ui
