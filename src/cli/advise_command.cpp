// particle-lab advise: which force terms this scene needs, from running the models.
#include "cli/cli_support.hpp"

#include "io/json_csv.hpp"
#include "io/metrics_json.hpp"
#include "physics/studies/advisor.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <iostream>
#include <memory>

namespace pl::cli {

namespace {

struct AdviseCliOptions {
    std::string preset;
    std::vector<std::string> sets;  // --set KEY=VALUE
    AdviceOptions advice;
    bool json = false, csv = false;
};

using Json = nlohmann::ordered_json;

// --relative-tolerance: 0 (absolute tolerances only) or more.
CLI::Validator non_negative_number() {
    return CLI::Validator(
        [](std::string& text) -> std::string {
            double v = 0.0;
            const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
            if (text.empty() || r.ec != std::errc() || r.ptr != text.data() + text.size() || !std::isfinite(v) || v < 0.0)
                return fmt::format("must be a number >= 0, got '{}'", text);
            return "";
        },
        "NUMBER>=0");
}

Json optional_number(bool present, double value) { return present ? Json(value) : Json(nullptr); }

// Every metric of one comparison; the same keys in every run, null where not measured, so that
// --csv has one column per key.
Json metrics_json(const ModelRun& r) {
    Json metrics;
    for (AdviceMetric m : advice_metrics) {
        const MetricDelta& d = r.metric(m);
        Json x;
        x["difference"] = optional_number(d.measured, d.difference);
        x["value"] = optional_number(d.measured, d.value);
        x["baseline"] = optional_number(d.measured, d.baseline);
        const std::optional<double> rel = d.relative();
        x["relative"] = optional_number(rel.has_value(), rel.value_or(0.0));
        x["beyond_tolerance"] = d.beyond_tolerance;
        x["at_least"] = d.at_least;
        x["within_chaos"] = d.within_chaos;
        x["systematic"] = d.systematic;
        x["samples"] = d.samples;
        x["mean"] = optional_number(d.samples > 0, d.mean);
        x["standard_error"] = optional_number(d.samples > 1, d.standard_error);
        x["particle"] = d.measured ? Json(d.particle) : Json(nullptr);
        x["impact"] = m == AdviceMetric::impact_speed && d.measured ? Json(d.impact) : Json(nullptr);
        metrics[json_key(m)] = x;
    }
    return metrics;
}

Json run_json(const ModelRun& r) {
    Json jr;
    jr["drag"] = to_string(r.model);
    jr["with_wind"] = r.with_wind;
    jr["landing_difference_m"] = r.landing_difference_m;
    jr["apex_difference_m"] = r.apex_difference_m;
    jr["term"] = r.term;
    jr["kind"] = r.alternative ? "alternative" : "toggle";
    jr["in_scene"] = r.in_scene;
    jr["buoyancy"] = r.buoyancy;
    jr["not_applicable"] = r.not_applicable.empty() ? Json(nullptr) : Json(r.not_applicable);
    jr["matters"] = r.matters;
    jr["within_chaos"] = r.within_chaos;
    jr["metrics"] = metrics_json(r);
    return jr;
}

// The collision estimate (physics/studies/collision_estimate.hpp) and the recommendation; the
// numbers are null with fewer than two particles.
Json collisions_json(const VariantAdvice& va) {
    const CollisionEstimate& e = va.collisions;
    auto number = [&](double v) { return optional_number(e.applicable && std::isfinite(v), v); };
    Json c;
    c["applicable"] = e.applicable;
    c["particles"] = e.particles;
    c["measured_particles"] = e.measured_particles;
    c["room_volume_m3"] = number(e.room_volume_m3);
    c["number_density_m3"] = number(e.number_density_m3);
    c["volume_fraction"] = number(e.volume_fraction);
    c["cross_section_m2"] = number(e.cross_section_m2);
    c["mean_free_path_m"] = number(e.mean_free_path_m);
    c["speed_m_s"] = number(e.speed_m_s);
    c["rate_per_s"] = number(e.rate_per_s);
    c["duration_s"] = number(e.duration_s);
    c["expected_per_particle"] = number(e.per_particle);
    c["expected_total"] = number(e.total);
    c["floor_area_m2"] = number(e.floor_area_m2);
    c["footprint_m2"] = number(e.footprint_m2);
    c["layers"] = number(e.layers);
    c["must_stack"] = e.must_stack;
    c["estimate_matters"] = e.matters;
    c["recommended"] = va.collisions_recommended;
    c["reason"] = collision_reason(e);
    return c;
}

// The --json document; --csv writes its "variants" with one row per model run (io/json_csv.hpp).
Json advice_json(const Scene& scene, const Advice& a) {
    Json j = json_document();
    j["preset"] = scene.name;
    j["tolerance_m"] = a.tolerance_m;
    j["tolerance_s"] = a.tolerances.seconds;
    j["tolerance_m_s"] = a.tolerances.metres_per_second;
    j["relative_tolerance"] = a.tolerances.relative;
    j["max_duration_s"] = a.max_duration_s;
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
        x["buoyancy"] = va.buoyancy;
        x["reynolds_min"] = va.re_min;
        x["reynolds_max"] = va.re_max;
        x["max_drag_to_weight"] = va.max_drag_to_weight;
        x["max_mach"] = va.max_mach;
        x["stokes_error_factor"] = va.stokes_error_factor;
        x["cheapest_adequate_drag"] = to_string(va.cheapest_adequate);
        x["simulated_s"] = va.simulated_s;
        x["density_ratio"] = va.density_ratio;
        x["collisions"] = collisions_json(va);
        // With collisions on: the scene run again from moved starts (the same keys without, for --csv).
        x["chaos_measured"] = va.chaos_measured;
        x["chaos"] = run_json(va.chaos);
        Json runs = Json::array();
        for (const ModelRun& r : va.runs) runs.push_back(run_json(r));
        x["runs"] = runs;
        x["verdicts"] = va.verdicts;
        x["warnings"] = va.warnings;
        variants.push_back(x);
    }
    j["variants"] = variants;
    return j;
}

// A table cell: the difference in the metric's unit, ">=" for a bound, "*" beyond tolerance.
std::string cell(const MetricDelta& d) {
    if (!d.measured) return "-";
    return std::string(d.at_least ? (d.difference < 0 ? "<=" : ">=") : "") + sig(d.difference, 3) +
           (d.beyond_tolerance ? "*" : "") + (d.within_chaos ? "~" : "");
}

// One line: the estimate's numbers, over all the scene's particles.
void print_collision_estimate(const VariantAdvice& va) {
    const CollisionEstimate& e = va.collisions;
    if (!e.applicable) {
        std::printf("  collisions: %s\n", collision_reason(e).c_str());
        return;
    }
    std::printf("  collisions (estimate, %zu particles): n %s /m^3, volume fraction %s, mean free path %s m, speed %s m/s, "
                "%s per particle over %s s; %s layers on the floor; recommended %s\n",
                e.particles, sig(e.number_density_m3, 3).c_str(), sig(e.volume_fraction, 3).c_str(),
                sig(e.mean_free_path_m, 3).c_str(), sig(e.speed_m_s, 3).c_str(), sig(e.per_particle, 3).c_str(),
                sig(e.duration_s, 3).c_str(), sig(e.layers, 3).c_str(), va.collisions_recommended ? "on" : "off");
}

void print_variant(const Scene& scene, std::size_t v, const VariantAdvice& va) {
    std::printf("\nvariant %s  (drag %s, wind %s, buoyancy %s)\n", variant_name(scene, v).c_str(), to_string(va.configured),
                to_string(va.wind), va.buoyancy ? "on" : "off");
    std::printf("  Reynolds %s .. %s, max drag/weight %s, max Mach %s, rho_air/rho_particle up to %s\n",
                sig(va.re_min, 3).c_str(), sig(va.re_max, 3).c_str(), sig(va.max_drag_to_weight, 3).c_str(),
                sig(va.max_mach, 3).c_str(),
                sig(va.density_ratio.empty() ? 0.0 : *std::max_element(va.density_ratio.begin(), va.density_ratio.end()), 3)
                    .c_str());
    print_collision_estimate(va);
    Table t;
    t.header = {"  term", "in scene"};
    for (AdviceMetric m : advice_metrics) t.header.push_back(fmt::format("{} {}", to_string(m), unit_of(m)));
    t.header.push_back("matters");
    for (const ModelRun& r : va.runs) {
        std::vector<std::string> row = {"  " + r.term, r.in_scene ? "yes" : "no"};
        for (AdviceMetric m : advice_metrics) row.push_back(r.not_applicable.empty() ? cell(r.metric(m)) : "n/a");
        row.push_back(!r.not_applicable.empty() ? "n/a" : r.matters ? "yes" : "no");
        t.rows.push_back(row);
    }
    t.print();
    for (const std::string& s : va.verdicts) std::printf("  - %s\n", s.c_str());
    for (const std::string& s : va.warnings) std::printf("  warning: %s\n", s.c_str());
}

int advise_command(const AdviseCliOptions& o) {
    const std::optional<Scene> scene = load_scene("advise", o.preset, o.sets);
    if (!scene) return exit_bad_input;
    AdviceOptions options = o.advice;
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

    const AdviceTolerances& tol = a.tolerances;
    std::printf("%s: which terms matter, from running each term on and off (and each drag model against sphere_re)\n"
                "tolerances: %s mm, %s ms, %s mm/s%s; runs end when all particles rest, or at %s s\n"
                "table: the term's effect, on - off (drag models: model - sphere_re); * beyond tolerance, "
                "~ within the scene's chaos (see the warning)\n",
                scene->name.c_str(), sig(tol.metres * 1e3, 3).c_str(), sig(tol.seconds * 1e3, 3).c_str(),
                sig(tol.metres_per_second * 1e3, 3).c_str(),
                tol.relative > 0.0 ? fmt::format(" or {}% of the value", sig(tol.relative * 100.0, 3)).c_str() : "",
                sig(a.max_duration_s, 3).c_str());
    if (a.particles_used < a.particles_total)
        std::printf("(from the first %zu of %zu particles)\n", a.particles_used, a.particles_total);
    for (std::size_t v = 0; v < a.variants.size(); ++v) print_variant(*scene, v, a.variants[v]);
    return exit_ok;
}

}  // namespace

void add_advise_command(CLI::App& app, int& exit_code) {
    auto o = std::make_shared<AdviseCliOptions>();
    CLI::App* cmd = app.add_subcommand("advise", "which force terms this scene needs, and why");
    cmd->footer(
        "Which force terms does this scene need? Runs each variant's trajectories with each term on and\n"
        "off (drag, buoyancy, added mass, ISA air, collisions, wind) and with no, linear (Stokes),\n"
        "quadratic and sphere_re drag, and compares landing time, the first three impact speeds, time\n"
        "to rest, range, apex height and landing point. A term matters when any of them differs by\n"
        "more than max(its tolerance, --relative-tolerance x the value without the term, or with\n"
        "sphere_re for a drag model); the verdict names those metrics and by how much (on - off; drag\n"
        "models: model - sphere_re), for terms the scene has off too. Also reports the Reynolds range,\n"
        "drag/weight, Mach number and rho_air/rho_particle, and estimates the collision rate from the\n"
        "particle count, radii and room (mean free path; whether the balls must stack) to recommend\n"
        "collisions on or off. Runs stop when every particle rests, or at --duration.");
    cmd->add_option("PRESET", o->preset, "preset JSON file (-: standard input)")->required();
    add_set_option(cmd, o->sets);
    cmd->add_option("--tolerance", o->advice.tolerance_m, "tolerance of range, apex and landing point, m")
        ->capture_default_str()
        ->check(positive_number());
    cmd->add_option("--time-tolerance", o->advice.tolerance_s, "tolerance of landing time and time to rest, s")
        ->capture_default_str()
        ->check(positive_number());
    cmd->add_option("--speed-tolerance", o->advice.tolerance_mps, "tolerance of impact speeds, m/s")
        ->capture_default_str()
        ->check(positive_number());
    cmd->add_option("--relative-tolerance", o->advice.relative_tolerance,
                    "also within tolerance up to this fraction of the baseline value (0: absolute only)")
        ->capture_default_str()
        ->check(non_negative_number());
    cmd->add_option("--duration", o->advice.max_duration_s, "longest simulated time to wait for rest, s")
        ->capture_default_str()
        ->check(positive_number());
    auto* json = cmd->add_flag("--json", o->json, "print JSON");
    cmd->add_flag("--csv", o->csv, "print CSV, one row per variant and drag model run (the JSON, flattened)")->excludes(json);
    add_quiet_flag(cmd);
    cmd->callback([o, &exit_code] { exit_code = advise_command(*o); });
}

}  // namespace pl::cli
