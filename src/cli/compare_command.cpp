// particle-lab compare: one metrics row per variant, and the difference to a baseline variant.
#include "cli/cli_support.hpp"
#include "cli/resource_check.hpp"

#include "io/json_csv.hpp"
#include "io/metrics_json.hpp"
#include "physics/studies/metrics.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <iostream>
#include <memory>

namespace pl::cli {

namespace {

struct CompareCliOptions {
    std::string preset;
    std::vector<std::string> sets;  // --set KEY=VALUE
    double duration_s = 5.0;
    bool json = false, csv = false;
    std::string baseline;
    std::size_t particle = 0;
};

using Json = nlohmann::ordered_json;

Json difference_json(const MetricsDifference& d) {
    Json j;
    j["time_of_flight_s"] = optional_json(d.first_impact_time);
    j["range_at_first_impact_m"] = optional_json(d.range_at_first_impact);
    j["apex_height_m"] = d.apex_height;
    j["final_range_m"] = d.final_range;
    j["bounces"] = d.bounces;
    j["time_to_rest_s"] = optional_json(d.time_to_rest);
    j["all_at_rest_s"] = optional_json(d.all_at_rest_time);
    j["lost_to_drag_J"] = d.lost_drag;
    j["lost_to_bounces_J"] = d.lost_bounce;
    j["lost_to_friction_J"] = d.lost_friction;
    j["cost_s_per_s"] = d.cost;
    return j;
}

std::string signed_sig(const std::optional<double>& v) {
    if (!v) return "-";
    return (*v > 0 ? "+" : "") + sig(*v);
}

// The --json document; --csv writes its "variants" flattened (io/json_csv.hpp).
Json comparison_json(const Scene& scene, const Comparison& c, const CompareCliOptions& o, std::size_t baseline) {
    const VariantMetrics& base = c.variants[baseline];
    Json j = json_document();
    j["preset"] = scene.name;
    j["duration_s"] = c.duration_s;
    j["particle"] = o.particle;
    j["baseline"] = variant_label(scene, baseline);
    j["baseline_index"] = baseline;
    j["notes"] = "'particle' metrics are for the selected particle; 'all_particles' sums the energy over every "
                 "particle, and all_at_rest_s is the first time every particle is stopped";
    Json variants = Json::array();
    for (std::size_t v = 0; v < c.variants.size(); ++v) {
        const VariantMetrics& m = c.variants[v];
        Json jv;
        jv["label"] = variant_label(scene, v);
        jv["variant_index"] = v;
        jv["particle"] = particle_metrics_json(m.particles[o.particle]);
        Json all;
        all["all_at_rest_s"] = optional_json(m.all_at_rest_time);
        all["lost_to_drag_J"] = m.lost_drag;
        all["lost_to_bounces_J"] = m.lost_bounce;
        all["lost_to_friction_J"] = m.lost_friction;
        all["wind_work_J"] = m.wind_work;
        all["energy_residual_J"] = m.energy_residual;
        jv["all_particles"] = all;
        jv["steps"] = m.steps;
        jv["physics_time_s"] = m.physics_seconds;
        jv["cost_s_per_s"] = m.cost();
        jv["difference_to_baseline"] = difference_json(metrics_difference(m, base, o.particle));
        variants.push_back(jv);
    }
    j["variants"] = variants;
    // The preset's "expect" list beside what this run measured (any particle, not only --particle).
    j["expectations"] = expectations_json(check_expectations(scene.expect, c.variants));
    return j;
}

// The preset's expectations as a table after the metrics (nothing when it names none).
void print_expectations(const Scene& scene, const Comparison& c) {
    if (scene.expect.empty()) return;
    std::printf("\nexpected by the preset\n");
    Table t;
    t.header = {"quantity", "variant", "particle", "expected", "tolerance", "measured", ""};
    for (const ExpectationResult& r : check_expectations(scene.expect, c.variants))
        t.rows.push_back({to_string(r.expected.quantity), printable(variant_name(scene, r.expected.variant)),
                          std::to_string(r.expected.particle), sig(r.expected.value), sig(r.expected.tolerance),
                          sig(r.measured), r.met ? "met" : "NOT MET"});
    t.print();
}

int compare(const CompareCliOptions& o) {
    const std::optional<Scene> scene = load_scene("compare", o.preset, o.sets);
    if (!scene) return exit_bad_input;
    const std::size_t particles = initial_particles(*scene).size();
    if (o.particle >= particles) {
        print_error("compare", fmt::format("--particle: must be < {} (the number of particles), got {}", particles, o.particle));
        return exit_bad_input;
    }
    std::size_t baseline = 0;
    if (!o.baseline.empty()) {
        const std::optional<std::size_t> found = find_variant(*scene, o.baseline);
        if (!found) {
            print_error("compare", fmt::format("--baseline: no variant labelled or numbered '{}'; the variants are {}",
                                               o.baseline, variant_list(*scene)));
            return exit_bad_input;
        }
        baseline = *found;
    }
    const DurationPlan plan = plan_duration(*scene, o.duration_s);
    if (plan.error.empty())
        if (const std::string refused = check_work("compare", {particles, variant_count(*scene), double(plan.base_steps)});
            !refused.empty()) {
            print_error("compare", refused);
            return exit_bad_input;
        }
    Progress progress("compare");
    CompareOptions options;
    options.duration_s = o.duration_s;
    options.progress = [&](double f) { progress.update(f); };
    const Comparison c = run_comparison(*scene, options);
    progress.done();
    if (!c.error.empty()) {
        print_error("compare", "--duration: " + c.error);
        return exit_bad_input;
    }
    const VariantMetrics& base = c.variants[baseline];

    if (o.json || o.csv) {
        const Json j = comparison_json(*scene, c, o, baseline);
        if (o.json) std::cout << j.dump(2) << "\n";
        else write_json_rows_csv(std::cout, j["variants"]);
        return exit_ok;
    }

    std::printf("%s: %g s, particle %zu of %zu (energy and 'all rest' over all particles); baseline '%s'\n\n",
                printable(scene->name).c_str(), c.duration_s, o.particle, particles,
                printable(variant_name(*scene, baseline)).c_str());
    Table t;
    t.header = {"variant", "flight s", "apex m", "range@1st m", "final range m", "bounces", "rest s",
                "all rest s", "drag J", "bounce J", "friction J", "cost ms/s"};
    for (std::size_t v = 0; v < c.variants.size(); ++v) {
        const VariantMetrics& m = c.variants[v];
        const ParticleMetrics& p = m.particles[o.particle];
        t.rows.push_back({printable(variant_name(*scene, v)), sig(p.first_impact_time), sig(p.apex_height), sig(p.range_at_first_impact),
                          sig(p.final_range), std::to_string(p.bounces), sig(p.time_to_rest), sig(m.all_at_rest_time),
                          sig(m.lost_drag), sig(m.lost_bounce), sig(m.lost_friction), sig(m.cost() * 1e3, 3)});
    }
    t.print();
    std::printf("\ndifference to '%s' (variant - baseline)\n", printable(variant_name(*scene, baseline)).c_str());
    Table d;
    d.header = {"variant", "flight s", "apex m", "range@1st m", "final range m", "bounces", "rest s", "drag J",
                "bounce J", "friction J", "cost ms/s"};
    for (std::size_t v = 0; v < c.variants.size(); ++v) {
        const MetricsDifference x = metrics_difference(c.variants[v], base, o.particle);
        d.rows.push_back({printable(variant_name(*scene, v)), signed_sig(x.first_impact_time), signed_sig(x.apex_height),
                          signed_sig(x.range_at_first_impact), signed_sig(x.final_range),
                          (x.bounces > 0 ? "+" : "") + std::to_string(x.bounces), signed_sig(x.time_to_rest),
                          signed_sig(x.lost_drag), signed_sig(x.lost_bounce), signed_sig(x.lost_friction),
                          signed_sig(x.cost * 1e3)});
    }
    d.print();
    print_expectations(*scene, c);
    std::printf("\nflight: time to the first impact; range@1st: horizontal distance from the start to it; apex: highest\n"
                "centre height over the floor; rest: time the particle stopped for good; cost: physics wall time per\n"
                "simulated second.\n");
    return exit_ok;
}

}  // namespace

void add_compare_command(CLI::App& app, int& exit_code) {
    auto o = std::make_shared<CompareCliOptions>();
    CLI::App* cmd = app.add_subcommand("compare", "one metrics row per variant, and the difference to a baseline");
    cmd->footer(
        "Compare the variants of a preset: per variant the time of flight to the first bounce, apex\n"
        "height, range, bounces, time to rest, energy lost to drag/bounces/friction, cost (physics\n"
        "time per simulated second) and the difference to a baseline variant.");
    cmd->add_option("PRESET", o->preset, "preset JSON file (-: standard input)")->required();
    add_set_option(cmd, o->sets);
    cmd->add_option("--duration", o->duration_s, "simulated seconds; a whole number of every variant's steps")
        ->capture_default_str()
        ->check(positive_number());
    auto* json = cmd->add_flag("--json", o->json, "print JSON instead of a table");
    cmd->add_flag("--csv", o->csv, "print CSV, one row per variant (the JSON's variants, flattened)")->excludes(json);
    cmd->add_option("--baseline", o->baseline, "label of the baseline variant (default: the first)");
    cmd->add_option("--particle", o->particle, "particle whose trajectory metrics are shown")->capture_default_str()->check(whole_number_at_least(0));
    add_quiet_flag(cmd);
    cmd->callback([o, &exit_code] { exit_code = compare(*o); });
}

}  // namespace pl::cli
