// particle-lab run: every variant in lockstep; trajectory and events CSV, or a summary.
#include "cli/cli_support.hpp"

#include "cli/interrupt.hpp"
#include "cli/resource_check.hpp"
#include "cli/run_outputs.hpp"
#include "io/atomic_output.hpp"
#include "io/trajectory_table.hpp"
#include "physics/stepping/energy.hpp"
#include "physics/studies/metrics.hpp"
#include "physics/stepping/simulation.hpp"
#include "physics/stepping/thread_pool.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <memory>

namespace pl::cli {

namespace {

struct RunOptions {
    std::string preset;
    std::vector<std::string> sets;  // --set KEY=VALUE
    double duration_s = 5.0;
    RunOutputSpec output;
};

// Base steps between event drains. A particle raises at most a few events per step (a bounce on
// each of up to three walls at a corner, then rest, stop or lift); 8 per particle-step bounds
// that, so half the simulation's pending-event cap is never reached between drains.
std::uint64_t event_drain_interval(std::size_t particles) {
    constexpr std::uint64_t max_events_per_particle_step = 8;
    const std::uint64_t per_step = max_events_per_particle_step * std::max<std::uint64_t>(particles, 1);
    return std::max<std::uint64_t>(1, Simulation::max_pending_events / 2 / per_step);
}

// An output that would overwrite the preset being read, or the other output, is refused
// (standard output, "-", is never the preset; both on it is refused by RunOutputs).
std::string output_conflict(const RunOptions& o) {
    const auto is_file = [](const std::string& p) { return !p.empty() && p != "-"; };
    const RunOutputSpec& out = o.output;
    if (is_file(out.out) && o.preset != "-" && same_file(out.out, o.preset))
        return fmt::format("--out '{}' is the preset itself", out.out);
    if (is_file(out.events) && o.preset != "-" && same_file(out.events, o.preset))
        return fmt::format("--events '{}' is the preset itself", out.events);
    if (is_file(out.out) && is_file(out.events) && same_file(out.out, out.events))
        return fmt::format("--out and --events name the same file '{}'", out.out);
    return "";
}

// Warnings are raised once per particle and kind; a big scene can still raise thousands, so at
// most `per_kind` of each kind are printed, followed by how many more there were.
void print_warnings(const Simulation& sim, std::FILE* out, const std::string& prefix, std::size_t per_kind = 10) {
    std::array<std::size_t, warning_kind_count> seen{};
    for (const Warning& w : sim.warnings()) {
        const auto k = static_cast<std::size_t>(w.kind);
        if (k < seen.size() && seen[k]++ >= per_kind) continue;
        std::fprintf(out, "%s%s\n", prefix.c_str(), warning_message(w, sim.model()).c_str());
    }
    for (std::size_t k = 0; k < seen.size(); ++k)
        if (seen[k] > per_kind)
            std::fprintf(out, "%s... and %zu more warnings of this kind (one per particle)\n", prefix.c_str(), seen[k] - per_kind);
}

void print_summary(const Scene& scene, const std::vector<Simulation>& sims, const std::vector<std::array<std::uint64_t, 5>>& event_counts) {
    std::printf("%s: %zu particle%s, %zu variant%s\n", printable(scene.name).c_str(), sims.front().particle_count(),
                sims.front().particle_count() == 1 ? "" : "s", sims.size(), sims.size() == 1 ? "" : "s");
    for (std::size_t v = 0; v < sims.size(); ++v) {
        const Simulation& sim = sims[v];
        const Model& m = sim.model();
        const EnergyBreakdown e = total_energy(sim.state(), m.world.gravity, m.room);
        const auto& n = event_counts[v];
        std::printf("\nvariant %s  (%s, dt = %s s, drag %s, wind %s)\n", printable(variant_name(scene, v)).c_str(),
                    to_string(m.integrator.method), sig(m.integrator.dt, 6).c_str(), to_string(m.drag.model),
                    to_string(m.world.wind.kind));
        std::printf("  time %s s, %llu steps\n", sig(sim.time(), 10).c_str(), static_cast<unsigned long long>(sim.step_count()));
        std::printf("  events: %llu bounce, %llu rest, %llu stop, %llu lift, %llu frozen\n",
                    static_cast<unsigned long long>(n[0]), static_cast<unsigned long long>(n[1]),
                    static_cast<unsigned long long>(n[2]), static_cast<unsigned long long>(n[3]),
                    static_cast<unsigned long long>(n[4]));
        std::printf("  energy (J, all particles): initial %s = kinetic %s + potential %s\n"
                    "    + dissipated by bounces %s, friction %s, drag %s - wind work %s + residual %s\n",
                    sig(e.initial, 8).c_str(), sig(e.kinetic, 8).c_str(), sig(e.potential, 8).c_str(),
                    sig(e.dissipated_bounce, 8).c_str(), sig(e.dissipated_friction, 8).c_str(),
                    sig(e.dissipated_drag, 8).c_str(), sig(e.wind_work, 8).c_str(), sig(e.residual(), 3).c_str());
        if (spin_matters(m))
            std::printf("    + spin kinetic %s + dissipated by rolling resistance %s\n",
                        sig(e.spin, 8).c_str(), sig(e.dissipated_rolling, 8).c_str());
        if (m.collisions.enabled)
            std::printf("  collisions: %llu impulses; collision work %s J (minus what they dissipated)\n",
                        static_cast<unsigned long long>(sim.collisions_total()), sig(e.collision_work, 8).c_str());
        const ForceCounters& c = sim.counters();
        std::printf("  force evaluations: gravity %llu, drag %llu, wind %llu; time-of-impact solves %llu",
                    static_cast<unsigned long long>(c.gravity), static_cast<unsigned long long>(c.drag),
                    static_cast<unsigned long long>(c.wind), static_cast<unsigned long long>(c.contacts));
        if (m.integrator.method == Method::dopri5 && m.integrator.adaptive)
            std::printf("; dopri5 internal steps %llu accepted, %llu rejected",
                        static_cast<unsigned long long>(c.accepted_steps), static_cast<unsigned long long>(c.rejected_steps));
        std::printf("\n");
        print_warnings(sim, stdout, "  warning: ");
    }
}

int run(const RunOptions& o) {
    const std::optional<Scene> scene = load_scene("run", o.preset, o.sets);
    if (!scene) return exit_bad_input;
    const DurationPlan plan = plan_duration(*scene, o.duration_s);
    if (!plan.error.empty()) {
        print_error("run", "--duration: " + plan.error);
        return exit_bad_input;
    }
    if (const std::string refused = check_work("run", work_of(*scene, double(plan.base_steps))); !refused.empty()) {
        print_error("run", refused);
        return exit_bad_input;
    }
    if (const std::string conflict = output_conflict(o); !conflict.empty()) {
        print_error("run", conflict);
        return exit_bad_input;
    }
    const InterruptGuard interrupt;
    const std::vector<ParticleSpec> particles = initial_particles(*scene);
    RunOutputs outputs;
    if (const int code = outputs.open(o.output, particles.size(), plan.base_steps, variant_count(*scene)); code != exit_ok)
        return code;

    std::vector<Simulation> sims;
    std::vector<std::string> labels;  // in CSV the label itself (empty when none), beside variant_index
    for (std::size_t v = 0; v < variant_count(*scene); ++v) {
        sims.emplace_back(model_for_variant(*scene, v), particles);
        sims.back().set_threads(hardware_threads());  // explicit: no hardware query per step
        labels.push_back(variant_label(*scene, v));
    }
    std::vector<std::uint64_t> written_step(sims.size(), 0);
    std::vector<std::array<std::uint64_t, 5>> event_counts(sims.size(), {0, 0, 0, 0, 0});
    if (outputs.trajectory())
        for (std::size_t v = 0; v < sims.size(); ++v) outputs.write_states(sims[v], labels[v], v);

    Progress progress("run", plan.base_steps, "steps");
    // Every variant advances from one output point to the next in one step_n, which lets the
    // kernel take several steps per call (much faster for large scenes). Output points: every
    // K-th base step when writing CSV (K = --every), else every 256 for the progress line.
    // Events are drained at least every `drain` steps, fewer than the simulation keeps pending
    // (it drops beyond max_pending_events), so none is lost whatever K is. Splitting a step_n
    // changes no result.
    const std::uint64_t stride = outputs.trajectory() || outputs.events() ? std::max<std::uint64_t>(o.output.every, 1) : 256;
    const std::uint64_t drain = std::min(stride, event_drain_interval(particles.size()));
    // The next stop: a drain point or the next output point (a multiple of K), whichever is first.
    const auto next_stop = [&](std::uint64_t k) {
        return std::min({k + drain, (k / stride + 1) * stride, plan.base_steps});
    };
    for (std::uint64_t k = next_stop(0);; k = next_stop(k)) {
        const bool last = k == plan.base_steps;
        const bool output_point = k % stride == 0 || last;
        for (std::size_t v = 0; v < sims.size(); ++v) {
            // A variant with a coarser dt is written at base step k only if one of its steps ends there.
            const std::uint64_t before_k = sims[v].steps_to(static_cast<double>(k - 1) * plan.base_dt);
            const std::uint64_t taken = catch_up(sims[v], static_cast<double>(k) * plan.base_dt);
            if (taken == 0 && !last) continue;
            const std::vector<Event> new_events = sims[v].drain_events();
            for (const Event& e : new_events) ++event_counts[v][static_cast<std::size_t>(e.kind)];
            if (outputs.events()) outputs.write_events(new_events, labels[v], v);
            if (outputs.trajectory() && output_point && (taken > before_k || last) && sims[v].step_count() != written_step[v]) {
                // The last state is at t = duration (plan_duration checked every dt divides it).
                outputs.write_states(sims[v], labels[v], v);
                written_step[v] = sims[v].step_count();
            }
        }
        if (const int signal = InterruptGuard::received(); signal != 0) {
            progress.done();
            print_error("run", fmt::format("interrupted by {} at t = {} s; no output file was changed",
                                           signal_name(signal), sig(sims.front().time(), 6)));
            return 128 + signal;  // the outputs remove their temporary files
        }
        progress.update_count(k);
        if (last) break;
    }
    progress.done();
    for (const Simulation& sim : sims)
        if (sim.dropped_events() > 0) {  // a bug in the drain interval: never silently
            print_error("run", fmt::format("{} events of variant '{}' were lost", sim.dropped_events(), sim.model().label));
            return exit_runtime_failure;
        }
    if (const int code = outputs.close(); code != exit_ok) return code;
    // The summary goes to standard output unless an output does; then only the warnings remain.
    if (!outputs.trajectory() && !outputs.to_stdout()) {
        print_summary(*scene, sims, event_counts);
    } else if (!quiet()) {
        for (const Simulation& sim : sims)
            print_warnings(sim, stderr, fmt::format("particle-lab run: warning ({}): ", sim.model().label));
    }
    return exit_ok;
}

}  // namespace

void add_run_command(CLI::App& app, int& exit_code) {
    auto o = std::make_shared<RunOptions>();
    CLI::App* cmd = app.add_subcommand("run", "run a preset headless; trajectory and events CSV, or a summary");
    cmd->footer(
        "Run a preset headless: every variant in lockstep for --duration seconds.\n"
        "Writes the trajectory CSV (--out) and the events CSV (--events); without --out prints a\n"
        "summary per variant: time, steps, events, energy ledger, force evaluations, warnings.");
    cmd->add_option("PRESET", o->preset, "preset JSON file (-: standard input)")->required();
    add_set_option(cmd, o->sets);
    cmd->add_option("--duration", o->duration_s, "simulated seconds; a whole number of every variant's steps")
        ->capture_default_str()
        ->check(positive_number());
    cmd->add_option("--out", o->output.out,
                    "trajectory CSV (-: standard output; NAME.npy: NumPy binary, see docs/cli.md):\n" +
                        trajectory_column_names() +
                        "\n(initial state, every K-th step, final state at t = duration; t_s = step x dt)");
    cmd->add_option("--events", o->output.events, std::string("events CSV (-: standard output):\n") + event_columns);
    cmd->add_option("--particles", o->output.particles, "write only these particles to --out and --events, e.g. 0,3-5")
        ->type_name("LIST");
    cmd->add_option("--every", o->output.every, "write every K-th base step to --out")
        ->capture_default_str()
        ->check(positive_integer());
    add_quiet_flag(cmd);
    cmd->callback([o, &exit_code] { exit_code = run(*o); });
}

}  // namespace pl::cli
