// particle-lab accuracy: work-precision table (error vs cost per method and step size).
#include "cli/cli_support.hpp"
#include "cli/resource_check.hpp"

#include "io/metrics_json.hpp"
#include "physics/studies/accuracy_study.hpp"
#include "io/csv_writer.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <iostream>
#include <memory>

namespace pl::cli {

namespace {

struct AccuracyCliOptions {
    std::string preset;
    std::vector<std::string> sets;  // --set KEY=VALUE
    std::string methods, dts, tolerances, variant;
    double duration_s = 2.0;
    std::size_t particle = 0;
    bool dopri5_fixed = false;
    bool csv = false, json = false;
};

using Json = nlohmann::ordered_json;

std::optional<double> order_of(const AccuracyReport& r, Method m) {
    for (const MethodOrder& o : r.orders)
        if (o.method == m) return o.observed;
    return std::nullopt;
}

void print_csv(const AccuracyReport& r) {
    CsvWriter csv(std::cout);
    for (const char* h : {"method", "adaptive", "dt_s", "tol", "steps", "force_evaluations", "wall_s_per_simulated_s",
                          "position_error_m", "velocity_error_m_s", "bounce_time_error_s", "impacts", "impacts_matched",
                          "reference_impacts", "observed_order", "error_floor_m"})
        csv.field(h);
    csv.end_row();
    for (const AccuracyRow& row : r.rows) {
        csv.field(to_string(row.method)).field(row.adaptive ? "1" : "0").field(row.dt);
        if (row.adaptive) csv.field(row.tolerance);
        else csv.field("");
        csv.field(row.steps).field(row.force_evaluations).field(row.wall_seconds_per_sim_second);
        csv.field(row.position_error).field(row.velocity_error);
        if (row.bounce_time_error) csv.field(*row.bounce_time_error);
        else csv.field("");
        csv.field(static_cast<std::uint64_t>(row.impacts)).field(static_cast<std::uint64_t>(row.impacts_matched));
        csv.field(static_cast<std::uint64_t>(r.reference_impacts));
        const std::optional<double> order = row.adaptive ? std::nullopt : order_of(r, row.method);
        if (order) csv.field(*order);
        else csv.field("");
        csv.field(row.error_floor);
        csv.end_row();
    }
}

void print_json(const AccuracyReport& r, const std::string& preset) {
    Json j = json_document();
    j["preset"] = preset;
    j["variant"] = r.variant_label;
    j["particle"] = r.particle;
    j["duration_s"] = r.duration_s;
    j["reference"] = r.reference;
    j["reference_impacts"] = r.reference_impacts;
    j["reference_error_m"] = r.reference_error;
    Json rows = Json::array();
    for (const AccuracyRow& row : r.rows) {
        Json x;
        x["method"] = to_string(row.method);
        x["adaptive"] = row.adaptive;
        x["dt_s"] = row.dt;
        x["tol"] = row.adaptive ? Json(row.tolerance) : Json(nullptr);
        x["steps"] = row.steps;
        x["force_evaluations"] = row.force_evaluations;
        x["wall_s_per_simulated_s"] = row.wall_seconds_per_sim_second;
        x["position_error_m"] = row.position_error;
        x["error_floor_m"] = row.error_floor;
        x["velocity_error_m_s"] = row.velocity_error;
        x["bounce_time_error_s"] = row.bounce_time_error ? Json(*row.bounce_time_error) : Json(nullptr);
        x["impacts"] = row.impacts;
        x["impacts_matched"] = row.impacts_matched;
        rows.push_back(x);
    }
    j["rows"] = rows;
    Json orders = Json::array();
    for (const MethodOrder& o : r.orders) {
        Json x;
        x["method"] = to_string(o.method);
        x["expected"] = o.expected;
        x["observed"] = o.observed ? Json(*o.observed) : Json(nullptr);
        x["points"] = o.points;
        x["rows"] = o.rows;
        x["too_few_points"] = o.too_few_points;
        x["note"] = o.note();
        orders.push_back(x);
    }
    j["orders"] = orders;
    std::cout << j.dump(2) << "\n";
}

void print_table(const AccuracyReport& r, const std::string& preset) {
    std::printf("%s, variant '%s', particle %zu, t = %g s\nreference: %s (%zu impacts)\n\n", preset.c_str(),
                r.variant_label.c_str(), r.particle, r.duration_s, r.reference.c_str(), r.reference_impacts);
    Table t;
    t.header = {"method", "dt s", "tol", "steps", "force evals", "wall s/sim s", "pos err m", "floor m", "vel err m/s",
                "bounce t err s", "impacts"};
    for (const AccuracyRow& row : r.rows)
        t.rows.push_back({to_string(row.method), sig(row.dt), row.adaptive ? sig(row.tolerance, 2) : "-",
                          std::to_string(row.steps), std::to_string(row.force_evaluations),
                          sig(row.wall_seconds_per_sim_second, 3), sig(row.position_error, 3), sig(row.error_floor, 2),
                          sig(row.velocity_error, 3),
                          sig(row.bounce_time_error, 3),
                          fmt::format("{}/{}", row.impacts_matched, r.reference_impacts)});
    t.print();
    std::printf("\nobserved order (least-squares slope of log position error vs log dt over the rows whose error is at\n"
                "least %g x their floor: the reference's error, %s m, plus the run's round-off, steps x eps x (1 + |x|))\n",
                order_floor_margin, sig(r.reference_error, 3).c_str());
    Table o;
    o.header = {"method", "expected", "observed", "points", "note"};
    for (const MethodOrder& m : r.orders)
        o.rows.push_back({to_string(m.method), std::to_string(m.expected), sig(m.observed, 3),
                          fmt::format("{}/{}", m.points, m.rows), m.note()});
    o.print();
    std::printf("\nimpacts: matched in order (same wall) / in the reference. points: rows above the floor / rows.\n");
}

int accuracy(const AccuracyCliOptions& o) {
    AccuracyOptions options;
    options.duration_s = o.duration_s;
    options.particle = o.particle;
    options.dopri5_fixed_step = o.dopri5_fixed;
    std::string error;
    if (!o.methods.empty()) error = parse_method_list("--methods", o.methods, options.methods);
    if (error.empty() && !o.dts.empty()) error = parse_double_list("--dt", o.dts, options.dts);
    if (error.empty() && !o.tolerances.empty()) error = parse_double_list("--tol", o.tolerances, options.tolerances);
    if (!error.empty()) {
        print_error("accuracy", error);
        return exit_bad_input;
    }
    const std::optional<Scene> scene = load_scene("accuracy", o.preset, o.sets);
    if (!scene) return exit_bad_input;
    if (!o.variant.empty()) {
        const std::optional<std::size_t> found = find_variant(*scene, o.variant);
        if (!found) {
            print_error("accuracy", fmt::format("--variant: no variant labelled or numbered '{}'; the variants are {}",
                                                o.variant, variant_list(*scene)));
            return exit_bad_input;
        }
        options.variant = *found;
    }
    double steps = 0.0;  // over the --dt ladder; the default ladder is the preset's own dt and coarser
    for (double dt : options.dts) steps += o.duration_s / dt;
    if (const std::string refused = check_work("accuracy", {1, 1, steps}); !refused.empty()) {
        print_error("accuracy", "--dt: " + refused);
        return exit_bad_input;
    }
    Progress progress("accuracy");
    options.progress = [&](double f) { progress.update(f); };
    const AccuracyReport r = run_accuracy_study(*scene, options);
    progress.done();
    if (!r.error.empty()) {
        print_error("accuracy", r.error);
        return exit_bad_input;
    }
    if (o.csv) print_csv(r);
    else if (o.json) print_json(r, scene->name);
    else print_table(r, scene->name);
    return exit_ok;
}

}  // namespace

void add_accuracy_command(CLI::App& app, int& exit_code) {
    auto o = std::make_shared<AccuracyCliOptions>();
    CLI::App* cmd = app.add_subcommand("accuracy", "work-precision: error vs cost per method and step size");
    cmd->footer(
        "Measure the speed/accuracy trade on a preset: one particle of one variant run with each\n"
        "method over a ladder of step sizes (tolerances for adaptive dopri5), against a reference\n"
        "(closed form where one exists, else dopri5 at rtol = atol = 1e-12). Prints steps, force\n"
        "evaluations, wall time per simulated second, position/velocity error at the end, bounce-time\n"
        "error, and each method's observed order.");
    cmd->add_option("PRESET", o->preset, "preset JSON file (-: standard input)")->required();
    add_set_option(cmd, o->sets);
    cmd->add_option("--methods", o->methods,
                    "comma-separated methods (default: all): explicit_euler, semi_implicit_euler,\n"
                    "velocity_verlet, rk4, dopri5, exponential");
    cmd->add_option("--dt", o->dts, "comma-separated step sizes, s (default: 5 halving from 4x the preset's dt)");
    cmd->add_option("--tol", o->tolerances, "comma-separated dopri5 tolerances (default: 1e-3,...,1e-9)");
    cmd->add_option("--duration", o->duration_s, "simulated seconds (rounded up to a whole number of the largest dt)")
        ->capture_default_str()
        ->check(positive_number());
    cmd->add_option("--variant", o->variant, "variant label or index (default: the first)");
    cmd->add_option("--particle", o->particle, "particle index")->capture_default_str()->check(whole_number_at_least(0));
    cmd->add_flag("--dopri5-fixed", o->dopri5_fixed, "run dopri5 over the dt ladder at fixed step instead of over tolerances");
    auto* csv = cmd->add_flag("--csv", o->csv, "print CSV (full precision)");
    auto* json = cmd->add_flag("--json", o->json, "print JSON");
    csv->excludes(json);
    add_quiet_flag(cmd);
    cmd->callback([o, &exit_code] { exit_code = accuracy(*o); });
}

}  // namespace pl::cli
