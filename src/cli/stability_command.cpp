// particle-lab stability: the extremes grid, classified cell by cell.
#include "cli/cli_support.hpp"

#include "io/metrics_json.hpp"
#include "io/csv_writer.hpp"
#include "physics/studies/stability_study.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <iostream>
#include <map>
#include <memory>

namespace pl::cli {

namespace {

struct StabilityCliOptions {
    std::string preset;
    std::vector<std::string> sets;  // --set KEY=VALUE
    bool csv = false, json = false, quick = false;
    unsigned threads = 0;
};

using Json = nlohmann::ordered_json;

char outcome_letter(StabilityOutcome o) {
    switch (o) {
        case StabilityOutcome::stable: return '.';
        case StabilityOutcome::energy_growth: return 'E';
        case StabilityOutcome::nan: return 'N';
        case StabilityOutcome::escaped: return 'X';
        case StabilityOutcome::jitter: return 'J';
        case StabilityOutcome::tunnelled: return 'T';
        case StabilityOutcome::overlap: return 'O';
    }
    return '?';
}

void cells_csv(CsvWriter& csv, const std::vector<StabilityCell>& cells, const char* slice) {
    for (const StabilityCell& c : cells) {
        csv.field(slice).field(to_string(c.c.method)).field(c.c.dt).field(c.c.stiffness).field(c.c.speed);
        csv.field(c.c.restitution).field(c.c.radius_fraction).field(to_string(c.outcome)).field(c.steps);
        csv.field(c.simulated_s).field(c.max_energy_ratio).field(c.jitter_checked ? "1" : "0").field(c.detail);
        if (c.c.pair()) csv.field(c.c.pair_radius_ratio).field(c.c.pair_mass_ratio).field(c.max_overlap).field(c.collision_warned ? "1" : "0");
        else csv.field("").field("").field("").field("");
        csv.end_row();
    }
}

Json cell_json(const StabilityCell& c) {
    Json j;
    j["method"] = to_string(c.c.method);
    j["dt_s"] = c.c.dt;
    j["k_per_s"] = c.c.stiffness;
    j["speed_m_s"] = c.c.speed;
    j["restitution"] = c.c.restitution;
    j["radius_fraction"] = c.c.radius_fraction;
    j["outcome"] = to_string(c.outcome);
    j["steps"] = c.steps;
    j["simulated_s"] = c.simulated_s;
    j["max_energy_ratio"] = c.max_energy_ratio;
    j["jitter_checked"] = c.jitter_checked;
    j["detail"] = c.detail;
    if (c.c.pair()) {
        j["radius_ratio"] = c.c.pair_radius_ratio;
        j["mass_ratio"] = c.c.pair_mass_ratio;
        j["max_overlap"] = c.max_overlap;
        j["collision_warned"] = c.collision_warned;
    }
    return j;
}

// Per method: the cells and how many of each outcome, and how many `flagged` (a last column).
template <typename Flag>
void outcome_counts(const std::vector<StabilityCell>& cells, const std::vector<Method>& methods, const char* flag_name,
                    Flag flagged) {
    Table s;
    s.header = {"method", "cells"};
    for (std::size_t o = 0; o < stability_outcome_count; ++o) s.header.push_back(to_string(static_cast<StabilityOutcome>(o)));
    s.header.push_back(flag_name);
    for (Method m : methods) {
        std::array<int, stability_outcome_count> n{};
        int count = 0, flags = 0;
        for (const StabilityCell& c : cells)
            if (c.c.method == m) {
                ++n[static_cast<std::size_t>(c.outcome)];
                ++count;
                flags += flagged(c) ? 1 : 0;
            }
        std::vector<std::string> row{to_string(m), std::to_string(count)};
        for (int k : n) row.push_back(std::to_string(k));
        row.push_back(std::to_string(flags));
        s.rows.push_back(std::move(row));
    }
    s.print();
}

template <typename Describe>
void first_unstable(const std::vector<StabilityCell>& cells, const std::vector<Method>& methods, Describe describe) {
    for (Method m : methods) {
        int shown = 0;
        for (const StabilityCell& c : cells) {
            if (c.c.method != m || c.outcome == StabilityOutcome::stable) continue;
            if (shown++ == 5) break;
            std::printf("  %s %s: %s (%s)\n", to_string(m), describe(c).c_str(), to_string(c.outcome), c.detail.c_str());
        }
    }
}

void print_text(const StabilityReport& r, const StabilityGrid& g, const std::string& where) {
    std::printf("stability study in %s\n", where.c_str());
    std::printf("cells: one particle launched from the room's centre; k = linear drag stiffness b/m (1/s).\n"
                "energy_growth: KE + PE above E0 by more than %g E0 (no energy source in these cells);\n"
                "jitter: e < 1 but still bouncing on the floor after the time-to-rest bound.\n\n",
                stability_energy_tolerance);
    std::printf("largest stable dt: theory (method limit / k) beside the measured one (largest grid dt with every\n"
                "smaller dt stable; map at speed %g m/s, e = %g, radius %g of the room)\n",
                g.map_speed, g.map_restitution, g.map_radius_fraction);
    Table t;
    t.header = {"method", "k 1/s", "theory dt s", "measured dt s", "first unstable dt s"};
    for (const StabilityLimit& l : r.limits)
        t.rows.push_back({to_string(l.method), sig(l.stiffness, 3), std::isfinite(l.theoretical_dt) ? sig(l.theoretical_dt, 3) : "none",
                          !l.measured_dt ? "< grid" : (l.first_unstable_dt ? "" : ">= ") + sig(*l.measured_dt, 3),
                          sig(l.first_unstable_dt, 3)});
    t.print();

    std::printf("\nmaps (rows dt, columns k): . stable, E energy growth, N NaN, X escaped, J jitter, T tunnelled\n");
    std::string header = fmt::format("{:>10}", "dt \\ k");
    for (double k : g.stiffnesses) header += fmt::format(" {:>6}", sig(k, 2));
    for (Method m : g.methods) {
        std::printf("\n%s\n%s\n", to_string(m), header.c_str());
        for (double dt : g.dts) {
            std::string line = fmt::format("{:>10}", sig(dt, 3));
            for (double k : g.stiffnesses) {
                char letter = ' ';
                for (const StabilityCell& c : r.map_cells)
                    if (c.c.method == m && c.c.dt == dt && c.c.stiffness == k) letter = outcome_letter(c.outcome);
                line += fmt::format(" {:>6}", letter);
            }
            std::printf("%s\n", line.c_str());
        }
    }

    std::printf("\nsweep: dt x speed x restitution x radius at k in {");
    for (std::size_t i = 0; i < g.sweep_stiffnesses.size(); ++i) std::printf("%s%g", i ? ", " : "", g.sweep_stiffnesses[i]);
    std::printf("} 1/s: outcomes per method\n");
    outcome_counts(r.sweep_cells, g.methods, "jitter checked", [](const StabilityCell& c) { return c.jitter_checked; });
    std::printf("\nunstable sweep cells (first 5 per method; --csv lists every cell):\n");
    first_unstable(r.sweep_cells, g.methods, [](const StabilityCell& c) {
        return fmt::format("dt={} k={} speed={} e={} r={}", sig(c.c.dt, 3), sig(c.c.stiffness, 3), sig(c.c.speed, 3),
                           sig(c.c.restitution, 2), sig(c.c.radius_fraction, 2));
    });

    std::printf("\ncollisions: two balls thrown at each other (ball 0 of radius %g of the room, ball 1 the radius and\n"
                "mass ratios times it), dt x speed x restitution x radius ratio x mass ratio; overlap: left deeper than\n"
                "%g of the contact distance\n",
                g.pair_radius_fraction, collision_overlap_limit);
    outcome_counts(r.pair_cells, g.methods, "warned", [](const StabilityCell& c) { return c.collision_warned; });
    std::printf("\nunstable collision cells (first 5 per method):\n");
    first_unstable(r.pair_cells, g.methods, [](const StabilityCell& c) {
        return fmt::format("dt={} speed={} e={} radii 1:{} masses 1:{}", sig(c.c.dt, 3), sig(c.c.speed, 3),
                           sig(c.c.restitution, 2), sig(c.c.pair_radius_ratio, 3), sig(c.c.pair_mass_ratio, 3));
    });
}

int stability(const StabilityCliOptions& o) {
    StabilityBase base = default_stability_base();
    std::string where = "the seed's 2 m cube room (no preset given)";
    if (!o.preset.empty()) {
        const std::optional<Scene> scene = load_scene("stability", o.preset, o.sets);
        if (!scene) return exit_bad_input;
        base = stability_base(*scene);
        where = fmt::format("the room, gravity and contact of '{}'", scene->name);
    }
    StabilityOptions options;
    options.grid = default_stability_grid(o.quick);
    options.threads = o.threads;
    Progress progress("stability");
    options.progress = [&](double f) { progress.update(f); };
    const StabilityReport r = run_stability_study(base, options);
    progress.done();
    if (o.csv) {
        CsvWriter csv(std::cout);
        for (const char* h : {"slice", "method", "dt_s", "k_per_s", "speed_m_s", "restitution", "radius_fraction", "outcome", "steps",
                              "simulated_s", "max_energy_ratio", "jitter_checked", "detail", "radius_ratio", "mass_ratio",
                              "max_overlap", "collision_warned"})
            csv.field(h);
        csv.end_row();
        cells_csv(csv, r.map_cells, "map");
        cells_csv(csv, r.sweep_cells, "sweep");
        cells_csv(csv, r.pair_cells, "collisions");
    } else if (o.json) {
        Json j = json_document();
        j["energy_tolerance"] = stability_energy_tolerance;
        Json limits = Json::array();
        for (const StabilityLimit& l : r.limits) {
            Json x;
            x["method"] = to_string(l.method);
            x["k_per_s"] = l.stiffness;
            x["theoretical_dt_s"] = std::isfinite(l.theoretical_dt) ? Json(l.theoretical_dt) : Json(nullptr);
            x["measured_dt_s"] = optional_json(l.measured_dt);
            x["first_unstable_dt_s"] = optional_json(l.first_unstable_dt);
            limits.push_back(x);
        }
        j["limits"] = limits;
        j["collision_overlap_limit"] = collision_overlap_limit;
        for (const auto& [name, cells] : {std::pair{"map", &r.map_cells}, {"sweep", &r.sweep_cells}, {"collisions", &r.pair_cells}}) {
            Json list = Json::array();
            for (const StabilityCell& c : *cells) list.push_back(cell_json(c));
            j[name] = list;
        }
        std::cout << j.dump(2) << "\n";
    } else {
        print_text(r, options.grid, where);
    }
    return exit_ok;
}

}  // namespace

void add_stability_command(CLI::App& app, int& exit_code) {
    auto o = std::make_shared<StabilityCliOptions>();
    CLI::App* cmd =
        app.add_subcommand("stability", "extremes grid: stable / energy growth / NaN / escaped / jitter / tunnelled / overlap");
    cmd->footer(
        "Sweep the extremes: time step (1e-5 .. 0.5 s) x linear drag stiffness k (0 .. 1e4 1/s) for\n"
        "every method, and time step x launch speed (0 .. 1e3 m/s) x restitution (0, 0.5, 1) x radius\n"
        "(up to 0.49 of the room); and, with collisions, two balls thrown at each other: time step x\n"
        "speed (1 .. 100 m/s) x restitution x radius ratio (1, 10) x mass ratio (1e-3 .. 1e3). Each\n"
        "cell is classified stable, energy_growth, nan, escaped, jitter, tunnelled or (a pair left\n"
        "deeper in each other than 10% of the contact distance) overlap; the theoretical dt limit is\n"
        "printed beside the measured one.");
    cmd->add_option("PRESET", o->preset, "preset whose room, gravity, contact and particle mass to use\n"
                                         "(default: the seed's 2 m cube)");
    add_set_option(cmd, o->sets);
    cmd->add_flag("--quick", o->quick, "a small grid (a second or so)");
    cmd->add_option("--threads", o->threads, "worker threads (default: all cores)");
    auto* csv = cmd->add_flag("--csv", o->csv, "print every cell as CSV");
    auto* json = cmd->add_flag("--json", o->json, "print JSON");
    csv->excludes(json);
    add_quiet_flag(cmd);
    cmd->callback([o, &exit_code] { exit_code = stability(*o); });
}

}  // namespace pl::cli
