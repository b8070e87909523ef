#include "app/state_dump.hpp"

#include "app/picking.hpp"
#include "io/metrics_json.hpp"
#include "ui/expectations_view.hpp"
#include "ui/panel_state.hpp"
#include "ui/pinned_runs.hpp"
#include "ui/plot_history.hpp"
#include "ui/sections.hpp"
#include "ui/warning_risk.hpp"

#include <imgui.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>

namespace pl::app {

namespace {

nlohmann::json vec3(const Vec3& v) { return nlohmann::json::array({v.x, v.y, v.z}); }

// Where particle i appears in the window (ImGui coordinates = window pixels), or null.
nlohmann::json screen_position(const ViewSnapshot& view, std::size_t variant, const Vec3& x) {
    for (const ViewPane& pane : view.panes) {
        if (pane.variant && *pane.variant != variant) continue;
        const CameraMatrices cam = camera_matrices(view.camera, pane.rect.w / std::max(pane.rect.h, 1.0f));
        if (auto p = project(cam, pane.rect, glm::vec3(x)); p && pane.rect.contains(p->x, p->y))
            return nlohmann::json::array({p->x, p->y});
    }
    return nullptr;
}

// The first particles of each variant: enough for any test, and a dump of a million-particle
// scene (bench/gui_rtf.sh dumps one while its physics runs) stays small and quick.
constexpr std::size_t max_dumped_particles = 1000;

nlohmann::json variant_json(const Simulation& sim, std::size_t variant, const ViewSnapshot& view) {
    const ParticleState& st = sim.state();
    nlohmann::json particles = nlohmann::json::array();
    for (std::size_t i = 0; i < std::min(st.size(), max_dumped_particles); ++i)
        particles.push_back({{"position", vec3(st.position(i))},
                             {"velocity", vec3(st.velocity(i))},
                             {"resting_walls", st.resting[i]},
                             {"frozen", st.frozen[i] != 0},
                             {"screen", screen_position(view, variant, st.position(i))}});
    return {{"label", sim.model().label}, {"t", sim.time()}, {"steps", sim.step_count()},
            {"particle_count", st.size()}, {"particles", particles},
            {"collisions_total", sim.collisions_total()}, {"resting_contacts", sim.resting_contacts()},
            {"asleep_count", sim.asleep_count()}};
}

// The aim in progress: its velocity and, for checking the mapping, where the particle and the
// arrow's tip appear on screen (the tip should sit under the cursor).
nlohmann::json aim_json(const ui::LabSession& s, const ViewSnapshot& view) {
    const LaunchAim& aim = view.aim;
    if (!aim.active || !s.experiment || aim.variant >= s.experiment->variant_count() || aim.pane >= view.panes.size())
        return nullptr;
    const Simulation& run = s.experiment->run(aim.variant);
    if (aim.particle >= run.particle_count()) return nullptr;
    const Rect& r = view.panes[aim.pane].rect;
    const CameraMatrices cam = camera_matrices(view.camera, r.w / std::max(r.h, 1.0f));
    const double arrow_time_s = aim_arrow_time_s(run.model().room);
    const Vec3 anchor = run.state().position(aim.particle);
    auto on_screen = [&](const Vec3& x) -> nlohmann::json {
        if (auto p = project(cam, r, glm::vec3(x))) return nlohmann::json::array({p->x, p->y});
        return nullptr;
    };
    const ui::LaunchPolar p = ui::launch_polar(aim.velocity);
    return {{"variant", aim.variant},
            {"particle", aim.particle},
            {"velocity", vec3(aim.velocity)},
            {"speed", p.speed_mps},
            {"elevation_deg", p.elevation_deg},
            {"azimuth_deg", p.azimuth_deg},
            {"clamped", aim.clamped},
            {"arrow_time_s", arrow_time_s},
            {"cursor", {aim.cursor_x, aim.cursor_y}},
            {"anchor_screen", on_screen(anchor)},
            {"tip_screen", on_screen(anchor + aim.velocity * arrow_time_s)}};
}

// The first few warnings at risk, in the Warnings tab's order.
nlohmann::json warnings_json(const ui::LabSession& s) {
    nlohmann::json warnings = nlohmann::json::array();
    if (s.experiment)
        for (std::size_t v = 0; v < s.experiment->variant_count() && warnings.size() < 8; ++v)
            for (const Warning& w : s.experiment->run(v).warnings()) {
                if (warnings.size() == 8) break;
                if (ui::puts_number_at_risk(w, s.experiment->run(v)))
                    warnings.push_back({{"variant", v}, {"particle", w.particle}});
            }
    return warnings;
}

// Pinned runs, oldest first, with the metrics of the selected particle (null without) and the
// samples of each particle's ghost path.
nlohmann::json pinned_json(const ui::LabSession& s, std::size_t selected) {
    nlohmann::json pinned = nlohmann::json::array();
    if (const ui::PinBoard* board = ui::pins_if_any(s))
        for (const ui::PinnedRun& run : board->runs) {
            nlohmann::json metrics = nullptr;
            if (run.metrics && selected < run.metrics->particles.size())
                metrics = cli::particle_metrics_json(run.metrics->particles[selected]);
            nlohmann::json paths = nlohmann::json::array();
            for (const ui::PathSeries& path : run.paths) paths.push_back(path.size());
            pinned.push_back({{"number", run.number}, {"label", run.label}, {"t_end", run.t_end}, {"metrics", metrics},
                              {"path_samples", paths}});
        }
    return pinned;
}

// The recorder: running or not, frames sent, the file being written and the last one finished.
nlohmann::json record_json(const RecordControl* rec) {
    if (!rec) return nullptr;
    const bool active = rec->recorder.active();
    return {{"active", active},
            {"frames", active ? rec->recorder.frames() : 0},
            {"fps", active ? rec->recorder.settings().fps : rec->next.fps},
            {"file", active ? rec->recorder.settings().file.string() : std::string{}},
            {"last_file", rec->last_file.string()},
            {"error", rec->error}};
}

// The measuring tool: on or off, its points (with where they appear in the first pane showing
// their variant), and with two points the distance and time between them.
nlohmann::json measure_json(const ui::LabSession& s, const ViewSnapshot& view) {
    nlohmann::json points = nlohmann::json::array();
    for (const ui::MeasuredPoint& p : s.measure_points)
        points.push_back({{"position", vec3(p.position)}, {"t", p.t}, {"variant", p.variant}, {"particle", p.particle},
                          {"screen", screen_position(view, p.variant, p.position)}});
    nlohmann::json j = {{"active", s.measuring}, {"points", points}, {"distance_m", nullptr}, {"time_s", nullptr}};
    if (s.measure_points.size() == 2) {
        j["distance_m"] = glm::length(s.measure_points[1].position - s.measure_points[0].position);
        j["time_s"] = std::abs(s.measure_points[1].t - s.measure_points[0].t);
    }
    return j;
}

// The file dialog while it shows (null otherwise): mode, folder, filename, the overwrite question.
// The Advise tab's last result: per variant its verdicts, the terms that matter and whether it
// recommends collisions.
nlohmann::json advice_json(const ui::LabSession& s) {
    nlohmann::json j = {{"running", false}, {"variants", nlohmann::json::array()}};
    if (!s.panels) return j;
    j["running"] = s.panels->advice.running();
    if (!s.panels->advice.result()) return j;
    for (const VariantAdvice& v : s.panels->advice.result()->variants) {
        nlohmann::json matters = nlohmann::json::array();
        for (const ModelRun& r : v.runs)
            if (r.matters) matters.push_back(r.term);
        j["variants"].push_back({{"verdicts", v.verdicts},
                                 {"matters", matters},
                                 {"collisions_recommended", v.collisions_recommended}});
    }
    return j;
}

// The Stability tab's last result: the map's method, its cell count, the view shown, and the
// collision slice's cells by outcome with how many of the unstable ones were warned.
nlohmann::json stability_json(const ui::LabSession& s) {
    nlohmann::json j = {{"running", false}, {"view", 0}};
    if (!s.panels) return j;
    j["running"] = s.panels->stability.running();
    j["view"] = s.panels->stability_view;
    const ui::StabilityMap* m = s.panels->stability.result() ? &*s.panels->stability.result() : nullptr;
    if (!m) return j;
    j["method"] = to_string(m->settings.method);
    j["map_cells"] = m->cells.size();
    nlohmann::json outcomes = nlohmann::json::object();
    std::size_t unstable = 0, warned = 0;
    for (const StabilityCell& c : m->pair_cells) {
        outcomes[to_string(c.outcome)] = outcomes.value(to_string(c.outcome), 0) + 1;
        if (c.outcome == StabilityOutcome::stable) continue;
        ++unstable;
        warned += c.collision_warned ? 1 : 0;
    }
    j["pair_outcomes"] = outcomes;
    j["pair_unstable"] = unstable;
    j["pair_unstable_warned"] = warned;
    return j;
}

nlohmann::json file_dialog_json(const ui::LabSession& s) {
    if (!s.panels || !s.panels->file_dialog.visible) return nullptr;
    const ui::FileDialog& d = s.panels->file_dialog;
    static constexpr const char* modes[] = {"open", "save", "folder"};
    return {{"mode", modes[static_cast<int>(d.mode)]},
            {"dir", d.dir.string()},
            {"filename", d.filename},
            {"overwrite", d.overwrite ? nlohmann::json(d.overwrite->string()) : nlohmann::json(nullptr)},
            {"error", d.error}};
}

}  // namespace

std::string write_state_dump(const std::filesystem::path& file, const ui::LabSession& s, long frames,
                             const ViewSnapshot& view) {
    nlohmann::json j;
    j["frames"] = frames;
    j["preset"] = s.preset_path.string();
    j["dirty"] = s.dirty;
    j["paused"] = s.paused;
    j["time_scale"] = s.time_scale;
    j["selected_particle"] = s.selected_particle;
    j["selected_variant"] = s.selected_variant;
    j["launch_velocity"] = vec3(s.launch_velocity);
    j["error_popup"] = s.error_popup;
    j["show_help"] = s.show_help;
    j["scene_name"] = s.scene.name;
    j["scene_dt"] = s.scene.integrator.dt;
    // The question the unsaved-changes dialog asks, if any: "quit", "open" or "revert".
    static constexpr const char* pending_names[] = {"quit", "open", "revert"};
    j["pending"] = s.pending ? nlohmann::json(pending_names[static_cast<int>(s.pending->kind)]) : nlohmann::json(nullptr);
    j["status"] = s.status_message;
    j["collision_status"] = ui::collision_status(s);  // the status bar's collision counters
    // Whether a text field had the keyboard on the last frame (tests wait for it before typing).
    j["text_input"] = ImGui::GetCurrentContext() != nullptr && ImGui::GetIO().WantTextInput;
    const OrbitCamera& c = view.camera;
    nlohmann::json panes = nlohmann::json::array();
    nlohmann::json pane_variants = nlohmann::json::array();  // null: a pane of every variant overlaid
    for (const ViewPane& p : view.panes) {
        panes.push_back({p.rect.x, p.rect.y, p.rect.w, p.rect.h});
        pane_variants.push_back(p.variant ? nlohmann::json(*p.variant) : nlohmann::json(nullptr));
    }
    j["view"] = {{"trails", s.show_trails},
                 {"velocity", s.show_velocity},
                 {"wind", s.show_wind},
                 {"contacts", s.show_contacts},
                 {"tint_sleeping", s.tint_sleeping},
                 {"split", s.split_view},
                 {"camera", {{"target", {c.target.x, c.target.y, c.target.z}}, {"yaw", c.yaw}, {"pitch", c.pitch},
                             {"distance", c.distance}}},
                 // The camera's screen axes in the world (screen right, screen up).
                 {"right", vec3(Vec3(camera_right(c)))},
                 {"up", vec3(Vec3(camera_up(c)))},
                 {"panes", panes},
                 {"pane_variants", pane_variants},
                 {"aim", aim_json(s, view)}};
    nlohmann::json widgets = nlohmann::json::object();
    for (const auto& [name, r] : s.widget_rects) widgets[name] = {r[0], r[1], r[2], r[3]};
    j["widgets"] = widgets;
    j["warnings"] = warnings_json(s);
    j["warning_count"] = ui::warning_count(s);  // at risk; notes: out of range, error negligible
    j["note_count"] = ui::note_count(s);
    // The Compare tab's live metrics of the selected particle, one object per variant (null
    // without live metrics), named as `particle-lab compare --json` names them.
    nlohmann::json live = nullptr;
    const std::size_t selected = static_cast<std::size_t>(std::max(s.selected_particle, 0));
    if (s.experiment && s.history && s.history->trackers.size() == s.experiment->variant_count()) {
        live = nlohmann::json::array();
        for (std::size_t v = 0; v < s.experiment->variant_count(); ++v) {
            const VariantMetrics m = metrics_of(s.history->trackers[v], s.experiment->run(v));
            if (selected >= m.particles.size()) live.push_back(nullptr);
            else live.push_back(nlohmann::json(cli::particle_metrics_json(m.particles[selected])));
        }
    }
    j["live_metrics"] = live;
    j["pinned_runs"] = pinned_json(s, selected);
    j["recording"] = record_json(view.record);
    // The status bar's numbers (bench/gui_rtf.sh reads them).
    j["frame_stats"] = {{"fps", s.frame.fps},
                        {"real_time_factor", s.frame.real_time_factor},
                        {"physics_ms", s.frame.physics_ms},
                        {"render_ms", s.frame.render_ms},
                        {"substeps", s.frame.substeps},
                        {"behind", s.frame.behind}};
    j["file_dialog"] = file_dialog_json(s);
    j["export_question"] = ui::export_question_open(s);
    j["measure"] = measure_json(s, view);
    // The preset's expectations beside the live measurements, as `compare --json` lists them.
    j["expectations"] = cli::expectations_json(ui::live_expectations(s));
    // The Sweep tab's last result: points, points run, and per series the first axis's value
    // where the shown metric is largest.
    const ui::SweepSummary sweep = ui::sweep_summary(s);
    nlohmann::json best = nlohmann::json::array();
    for (const auto& [label, x] : sweep.best) best.push_back({{"series", label}, {"x", x}});
    j["sweep"] = {{"running", sweep.running}, {"points", sweep.points}, {"done", sweep.done}, {"best", best}};
    j["advice"] = advice_json(s);
    j["stability"] = stability_json(s);
    j["t"] = s.experiment ? s.experiment->time() : 0.0;
    j["base_steps"] = s.experiment ? s.experiment->base_steps() : 0;
    nlohmann::json variants = nlohmann::json::array();
    if (s.experiment)
        for (std::size_t v = 0; v < s.experiment->variant_count(); ++v)
            variants.push_back(variant_json(s.experiment->run(v), v, view));
    j["variants"] = variants;

    const std::filesystem::path tmp = file.string() + ".tmp";
    {
        std::ofstream out(tmp, std::ios::trunc);
        if (!out) return "cannot write " + tmp.string();
        out << j.dump(1) << '\n';
        if (!out.flush()) return "cannot write " + tmp.string();
    }
    std::error_code ec;
    std::filesystem::rename(tmp, file, ec);
    if (ec) return "cannot rename " + tmp.string() + " to " + file.string() + ": " + ec.message();
    return {};
}

}  // namespace pl::app
