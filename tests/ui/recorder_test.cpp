// The recorder samples the plots at fixed simulated intervals, never per frame: a long jump
// between two frames ("Next event") is sampled like a smooth run. Pinned runs keep what the
// live run recorded, labelled by what differs.
#include "io/preset_io.hpp"
#include "ui/frame_recorder.hpp"
#include "ui/lab_ui.hpp"
#include "ui/pinned_runs.hpp"

#include <gtest/gtest.h>

#include <algorithm>

namespace pl::ui {
namespace {

LabSession session_for(const char* preset) {
    const LoadResult r = load_preset(std::filesystem::path(PL_SOURCE_DIR) / "presets" / preset);
    EXPECT_TRUE(r.ok()) << r.error_text();
    LabSession s;
    s.open_preset(*r.scene, preset);
    return s;
}

// Steps as the shell's driver does (as many steps at once as record_step allows), for `seconds`,
// with a single frame at the end.
void run_without_frames(LabSession& s, double seconds) {
    std::uint64_t group = 1;
    while (s.experiment->time() < seconds) {
        s.experiment->step_base(group);
        group = std::max<std::uint64_t>(1, std::min<std::uint64_t>(record_step(s), 64));
    }
    record_frame(s);
}

double largest_gap(const SampleSeries& series) {
    double gap = 0.0;
    for (std::size_t k = 1; k < series.size(); ++k) gap = std::max(gap, series.times()[k] - series.times()[k - 1]);
    return gap;
}

TEST(Recorder, LedgerIsSampledAtAFixedIntervalBetweenFrames) {
    LabSession s = session_for("default.json");
    run_without_frames(s, 1.0);
    const PlotHistory& h = *s.history;
    const double dt = s.experiment->base_dt();
    const SampleSeries& kinetic = h.variants[0].ledger.kinetic;
    EXPECT_GT(kinetic.size(), 1.0 / (h.aggregate_interval_s() + dt));
    EXPECT_LE(largest_gap(kinetic), h.aggregate_interval_s() + dt + 1e-12);
    EXPECT_LE(largest_gap(h.variants[0].particles[0].height), h.particle_interval_s() + dt + 1e-12);
}

TEST(Recorder, AggregatesOfManyParticlesAreSampledAtAFixedInterval) {
    LabSession s = session_for("many_particles.json");
    run_without_frames(s, 0.3);
    const PlotHistory& h = *s.history;
    ASSERT_TRUE(h.aggregated());
    const double dt = s.experiment->base_dt();
    const SampleSeries& mean = h.variants[0].aggregate.height_mean;
    EXPECT_GT(mean.size(), 0.3 / (h.aggregate_interval_s() + dt) - 1.0);
    EXPECT_LE(largest_gap(mean), h.aggregate_interval_s() + dt + 1e-12);
}

TEST(PathSeries, ThinsEvenlyAndSkipsRest) {
    PathSeries p;
    for (int k = 0; k < 3 * static_cast<int>(PathSeries::capacity); ++k) p.push(k * 0.001, Vec3(k, 0, 0));
    EXPECT_LE(p.size(), PathSeries::capacity);
    for (std::size_t k = 1; k < p.size(); ++k) EXPECT_NEAR(p.time(k) - p.time(k - 1), p.interval_s(), 1e-9);
    const std::size_t before = p.size();
    for (int k = 0; k < 100; ++k) p.push(100.0 + k, p.position(p.size() - 1));  // at rest: nothing new
    EXPECT_EQ(p.size(), before);
}

TEST(PinnedRuns, LabelSaysWhatDiffersAndSurviveEdits) {
    LabSession s = session_for("default.json");
    run_without_frames(s, 2.0);
    pin_current_run(s);
    Scene edited = s.scene;
    edited.drag.cd = 0.6;
    s.apply_scene(edited);
    run_without_frames(s, 2.0);
    pin_current_run(s);
    const PinBoard& board = pins_of(s);
    ASSERT_EQ(board.runs.size(), 2u);
    EXPECT_EQ(board.runs[1].label, "run 2: Cd 0.6");
    ASSERT_TRUE(board.runs[0].metrics && board.runs[1].metrics);
    // More drag: a lower apex than the pinned run before it.
    EXPECT_LT(board.runs[1].metrics->particles[0].apex_height, board.runs[0].metrics->particles[0].apex_height);
    for (const PinnedRun& run : board.runs) {
        ParticleTrack track = run.particles[0];
        for (const SampleSeries* series : track.all()) EXPECT_LE(series->size(), PinBoard::max_samples);
    }
}

TEST(PinnedRuns, KeepsTheNewestTwelve) {
    LabSession s = session_for("default.json");
    run_without_frames(s, 0.1);
    for (int k = 0; k < 15; ++k) pin_current_run(s);
    const PinBoard& board = pins_of(s);
    ASSERT_EQ(board.runs.size(), PinBoard::max_pins);
    EXPECT_EQ(board.runs.front().number, 4);
    EXPECT_EQ(board.runs[1].label, "run 5: same settings");
    unpin(s, 5);
    EXPECT_EQ(board.runs.size(), PinBoard::max_pins - 1);
    clear_pins(s);
    EXPECT_TRUE(board.runs.empty());
}

TEST(PresetLaunch, ParticleZerosVelocityBecomesTheLaunchVelocity) {
    LabSession s = session_for("altitude_air.json");
    EXPECT_EQ(s.launch_velocity, Vec3(25.0, 10.0, 0.0));
}

}  // namespace
}  // namespace pl::ui
