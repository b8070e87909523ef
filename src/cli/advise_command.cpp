// particle-lab advise: which force terms this scene needs, from running the models.
#include "cli/cli_support.hpp"

#include "io/json_csv.hpp"
#include "io/metrics_json.hpp"
#include "physics/studies/advisor.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <iostream>
#include <memory>

namespace pl::cli {

namespace {

struct AdviseCliOptions {
    std::string preset;
    std::vector<std::string> sets;  // --set KEY=VALUE
    double tolerance_m = 1e-3;
    double max_duration_s = 20.0;
    bool json = false, csv = false;
};

using Json = nlohmann::ordered_json;

// The --json document; --csv writes its "variants" with one row per model run (io/json_csv.hpp).
Json advice_json(const Scene& scene, const Advice& a) {
    Json j = json_document();
    j["preset"] = scene.name;
    j["tolerance_m"] = a.tolerance_m;
    j["particles_used"] = a.particles_used;
    j["particles_total"] = a.particles_total;
    Json variants = Json::array();
    for (std::size_t v = 0; v < a.variants.size(); ++v) {
        const VariantAdvice& va = a.variants[v];
        Json x;
        x["label"] = variant_label(scene, v);
        x["variant_index"] = v;
        x["drag"] = to_string(va.configured);
        x["wind"] = to_string(va.wind);
        x["reynolds_min"] = va.re_min;
        x["reynolds_max"] = va.re_max;
        x["max_drag_to_weight"] = va.max_drag_to_weight;
        x["max_mach"] = va.max_mach;
        x["stokes_error_factor"] = va.stokes_error_factor;
        x["cheapest_adequate_drag"] = to_string(va.cheapest_adequate);
        Json runs = Json::array();
        for (const ModelRun& r : va.runs) {
            Json jr;
            jr["drag"] = to_string(r.model);
            jr["with_wind"] = r.with_wind;
            jr["landing_difference_m"] = r.landing_difference_m;
            jr["apex_difference_m"] = r.apex_difference_m;
            runs.push_back(jr);
        }
        x["runs"] = runs;
        x["verdicts"] = va.verdicts;
        x["warnings"] = va.warnings;
        variants.push_back(x);
    }
    j["variants"] = variants;
    return j;
}

int advise_command(const AdviseCliOptions& o) {
    const std::optional<Scene> scene = load_scene("advise", o.preset, o.sets);
    if (!scene) return exit_bad_input;
    AdviceOptions options;
    options.tolerance_m = o.tolerance_m;
    options.max_duration_s = o.max_duration_s;
    Progress progress("advise");
    options.progress = [&](double f) { progress.update(f); };
    const Advice a = advise(*scene, options);
    progress.done();

    if (o.json || o.csv) {
        const Json j = advice_json(*scene, a);
        if (o.json) std::cout << j.dump(2) << "\n";
        else write_json_rows_csv(std::cout, j["variants"], "runs");
        return exit_ok;
    }

    std::printf("%s: advice at %s mm tolerance, from running each drag model against sphere_re (the richest)\n",
                scene->name.c_str(), sig(a.tolerance_m * 1e3, 3).c_str());
    if (a.particles_used < a.particles_total)
        std::printf("(from the first %zu of %zu particles)\n", a.particles_used, a.particles_total);
    for (std::size_t v = 0; v < a.variants.size(); ++v) {
        const VariantAdvice& va = a.variants[v];
        std::printf("\nvariant %s  (drag %s, wind %s)\n", variant_name(*scene, v).c_str(), to_string(va.configured),
                    to_string(va.wind));
        std::printf("  Reynolds %s .. %s, max drag/weight %s, max Mach %s\n", sig(va.re_min, 3).c_str(),
                    sig(va.re_max, 3).c_str(), sig(va.max_drag_to_weight, 3).c_str(), sig(va.max_mach, 3).c_str());
        Table t;
        t.header = {"  model", "landing/position diff m", "apex diff m"};
        for (const ModelRun& r : va.runs)
            t.rows.push_back({"  " + std::string(to_string(r.model)) + (r.with_wind || va.wind == WindKind::none ? "" : " (no wind)"),
                              sig(r.landing_difference_m, 3), sig(r.apex_difference_m, 3)});
        t.print();
        for (const std::string& s : va.verdicts) std::printf("  - %s\n", s.c_str());
        for (const std::string& s : va.warnings) std::printf("  warning: %s\n", s.c_str());
    }
    return exit_ok;
}

}  // namespace

void add_advise_command(CLI::App& app, int& exit_code) {
    auto o = std::make_shared<AdviseCliOptions>();
    CLI::App* cmd = app.add_subcommand("advise", "which force terms this scene needs, and why");
    cmd->footer(
        "Which force terms does this scene need? Runs each variant's trajectories with no drag, linear\n"
        "(Stokes), quadratic and sphere_re drag (and without wind) and reports the Reynolds range,\n"
        "drag/weight ratio, Mach number and, per term, how much it moves the landing point and apex,\n"
        "with a verdict at --tolerance.");
    cmd->add_option("PRESET", o->preset, "preset JSON file (-: standard input)")->required();
    add_set_option(cmd, o->sets);
    cmd->add_option("--tolerance", o->tolerance_m, "landing/apex tolerance in metres")
        ->capture_default_str()
        ->check(positive_number());
    cmd->add_option("--duration", o->max_duration_s, "longest simulated time to wait for landing, s")
        ->capture_default_str()
        ->check(positive_number());
    auto* json = cmd->add_flag("--json", o->json, "print JSON");
    cmd->add_flag("--csv", o->csv, "print CSV, one row per variant and drag model run (the JSON, flattened)")->excludes(json);
    add_quiet_flag(cmd);
    cmd->callback([o, &exit_code] { exit_code = advise_command(*o); });
}

}  // namespace pl::cli
