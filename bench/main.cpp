// pl_bench: runs every benchmark (Google Benchmark flags work as usual, e.g.
// --benchmark_filter=engine/drag_walls) and then prints the ratio tables the README quotes:
// engine against the hand-fused limit and the object-oriented baseline, thread scaling,
// each integrator's cost relative to semi-implicit Euler, and the price of accuracy.
#include "physics/stepping/thread_pool.hpp"
#include "registry.hpp"
#include "workloads.hpp"

#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace pl::bench {

namespace {

struct Measured {
    std::vector<double> rates;            // particle-steps per second of wall time, one per repetition
    std::vector<double> cpu_rates;        // the same per second of this process's CPU time
    std::vector<double> seconds_per_run;  // wall time per iteration
    std::map<std::string, std::vector<double>> counters;  // every repetition's value of each
};

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// Median over the repetitions of a counter the benchmark reported (none: nullopt).
std::optional<double> counter(const Measured& m, const std::string& key) {
    const auto it = m.counters.find(key);
    if (it == m.counters.end() || it->second.empty()) return std::nullopt;
    return median(it->second);
}

// Shows the usual console output and keeps every run for the ratio tables.
class CollectingReporter : public benchmark::ConsoleReporter {
public:
    bool ReportContext(const Context& context) override { return ConsoleReporter::ReportContext(context); }
    void ReportRuns(const std::vector<Run>& runs) override {
        ConsoleReporter::ReportRuns(runs);
        for (const Run& r : runs) {
            if (r.error_occurred || r.run_type != Run::RT_Iteration || r.iterations == 0) continue;
            const std::string& name = r.run_name.function_name;
            Measured& m = results_[name];
            if (const auto it = r.counters.find(rate_counter); it != r.counters.end()) {
                m.rates.push_back(it->second.value);
                if (r.cpu_accumulated_time > 0.0)
                    m.cpu_rates.push_back(it->second.value * r.real_accumulated_time / r.cpu_accumulated_time);
            }
            if (name.find("/threads:") == std::string::npos || name.find("/threads:1") != std::string::npos) {
                single_thread_cpu_ += r.cpu_accumulated_time;
                single_thread_real_ += r.real_accumulated_time;
            }
            m.seconds_per_run.push_back(r.real_accumulated_time / static_cast<double>(r.iterations));
            for (const auto& [name, counter] : r.counters) m.counters[name].push_back(counter.value);
        }
    }

    std::optional<double> rate(const std::string& name) const {
        const auto it = results_.find(name);
        if (it == results_.end() || it->second.rates.empty()) return std::nullopt;
        return median(it->second.rates);
    }
    std::optional<double> cpu_rate(const std::string& name) const {
        const auto it = results_.find(name);
        if (it == results_.end() || it->second.cpu_rates.empty()) return std::nullopt;
        return median(it->second.cpu_rates);
    }
    // CPU time over wall time of the single-threaded runs: below 1 when other processes
    // competed for the cores while the benchmarks ran.
    double cpu_share() const { return single_thread_real_ > 0.0 ? single_thread_cpu_ / single_thread_real_ : 1.0; }
    // Median over the repetitions of a benchmark's counter `key`.
    std::optional<double> counter(const std::string& name, const std::string& key) const {
        const auto it = results_.find(name);
        return it == results_.end() ? std::nullopt : pl::bench::counter(it->second, key);
    }
    const Measured* find(const std::string& name) const {
        const auto it = results_.find(name);
        return it == results_.end() ? nullptr : &it->second;
    }

private:
    std::map<std::string, Measured> results_;
    double single_thread_cpu_ = 0.0, single_thread_real_ = 0.0;
};

std::string rate_text(std::optional<double> r) { return r ? fmt::format("{:.3g}", *r) : "-"; }
std::string ratio_text(std::optional<double> a, std::optional<double> b, const char* suffix = "") {
    return a && b ? fmt::format("{:.2f}{}", *a / *b, suffix) : "-";
}
std::string speedup_text(std::optional<double> s) { return s ? fmt::format("{:.2f}x", *s) : "-"; }

void print_comparison(const CollectingReporter& r, int all_threads) {
    bool any = false;
    for (std::size_t n : sizes)
        any = any || r.rate("engine/drag_walls/n:" + size_label(n) + "/threads:1") ||
              r.rate("kernel/drag_walls/n:" + size_label(n) + "/threads:1") ||
              r.rate("limit_hand_fused/drag_walls/n:" + size_label(n)) || r.rate("baseline_oo/drag_walls/n:" + size_label(n));
    if (!any) return;
    fmt::print("\n## Engine vs references: gravity + quadratic drag + six walls (particle-steps/s)\n\n");
    fmt::print("engine = Simulation::step() (kernel + event cap + monitor); kernel = the stepping kernel alone; "
               "generic = Simulation::step() with the scalar reference kernel.\n\n");
    fmt::print("| n | engine | kernel | generic | hand-fused limit | OO baseline | engine/limit | kernel/limit | "
               "engine/baseline | limit/baseline | engine, {0} threads | speed-up | kernel, {0} threads | speed-up |\n",
               all_threads);
    fmt::print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (std::size_t n : sizes) {
        const std::string size = size_label(n);
        const std::string all = "/threads:" + std::to_string(all_threads);
        const auto engine = r.rate("engine/drag_walls/n:" + size + "/threads:1");
        const auto engine_all = all_threads > 1 ? r.rate("engine/drag_walls/n:" + size + all) : std::nullopt;
        const auto kernel = r.rate("kernel/drag_walls/n:" + size + "/threads:1");
        const auto kernel_all = all_threads > 1 ? r.rate("kernel/drag_walls/n:" + size + all) : std::nullopt;
        const auto limit = r.rate("limit_hand_fused/drag_walls/n:" + size);
        const auto baseline = r.rate("baseline_oo/drag_walls/n:" + size);
        const auto generic = r.rate("engine_generic_kernel/drag_walls/n:" + size);
        if (!engine && !kernel && !limit && !baseline) continue;
        fmt::print("| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n", size,
                   rate_text(engine), rate_text(kernel), rate_text(generic), rate_text(limit), rate_text(baseline),
                   ratio_text(engine, limit),
                   ratio_text(kernel, limit), ratio_text(engine, baseline), ratio_text(limit, baseline),
                   rate_text(engine_all), ratio_text(engine_all, engine, "x"), rate_text(kernel_all),
                   ratio_text(kernel_all, kernel, "x"));
    }
    const double share = r.cpu_share();
    if (share > 0.9) return;
    fmt::print("\nThe machine was busy: single-threaded runs got {:.0f}% of a core, so the rates above are low and "
               "noisy.\nSingle-thread rates and ratios per second of CPU time (threaded runs cannot be corrected):\n\n",
               100.0 * share);
    fmt::print("| n | engine | kernel | hand-fused limit | OO baseline | engine/limit | kernel/limit | engine/baseline | "
               "limit/baseline |\n");
    fmt::print("|---|---|---|---|---|---|---|---|---|\n");
    for (std::size_t n : sizes) {
        const std::string size = size_label(n);
        const auto engine = r.cpu_rate("engine/drag_walls/n:" + size + "/threads:1");
        const auto kernel = r.cpu_rate("kernel/drag_walls/n:" + size + "/threads:1");
        const auto limit = r.cpu_rate("limit_hand_fused/drag_walls/n:" + size);
        const auto baseline = r.cpu_rate("baseline_oo/drag_walls/n:" + size);
        if (!engine && !kernel && !limit && !baseline) continue;
        fmt::print("| {} | {} | {} | {} | {} | {} | {} | {} | {} |\n", size, rate_text(engine), rate_text(kernel),
                   rate_text(limit), rate_text(baseline), ratio_text(engine, limit), ratio_text(kernel, limit),
                   ratio_text(engine, baseline), ratio_text(limit, baseline));
    }
}

// Several steps per call (Simulation::step_n, as the CLI and the GUI's frames take them): each
// block of particles takes all the steps while it is in cache. Against the limit as above (one
// pass over all particles per step) and the limit blocked the same way.
void print_steps(const CollectingReporter& r, int all_threads) {
    auto engine = [&](std::size_t n, int steps, int threads) -> std::optional<double> {
        const std::string tail = "/n:" + size_label(n) + "/threads:" + std::to_string(threads);
        if (threads > 1 && all_threads < 2) return std::nullopt;
        return steps == 1 ? r.rate("engine/drag_walls" + tail)
                          : r.rate("engine_steps/drag_walls/steps:" + std::to_string(steps) + tail);
    };
    auto blocked = [&](std::size_t n, int threads) -> std::optional<double> {
        if (threads > 1 && all_threads < 2) return std::nullopt;
        return r.rate("limit_hand_fused/drag_walls/steps:32/n:" + size_label(n) + "/threads:" + std::to_string(threads));
    };
    bool any = false;
    for (std::size_t n : sizes) any = any || engine(n, 32, 1);
    if (!any) return;
    fmt::print("\n## Several steps per call: gravity + quadratic drag + six walls (particle-steps/s)\n\n");
    fmt::print("engine = Simulation::step_n(steps), as the CLI and a GUI frame call it; limit = the hand-fused loop, "
               "one pass over the particles per step (as above) or blocked like step_n (32 steps per block of "
               "particles).\n\n");
    fmt::print("| n | engine, 1 step | 8 steps | 32 steps | limit | limit, blocked | engine 32 / limit | "
               "engine 32 / limit blocked | engine 32, {0} threads | speed-up | limit blocked, {0} threads | "
               "speed-up |\n",
               all_threads);
    fmt::print("|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (std::size_t n : sizes) {
        const auto e1 = engine(n, 1, 1), e8 = engine(n, 8, 1), e32 = engine(n, 32, 1);
        const auto e32_all = engine(n, 32, all_threads);
        const auto limit = r.rate("limit_hand_fused/drag_walls/n:" + size_label(n));
        const auto b32 = blocked(n, 1), b32_all = blocked(n, all_threads);
        fmt::print("| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n", size_label(n), rate_text(e1),
                   rate_text(e8), rate_text(e32), rate_text(limit), rate_text(b32), ratio_text(e32, limit),
                   ratio_text(e32, b32), rate_text(e32_all), ratio_text(e32_all, e32, "x"), rate_text(b32_all),
                   ratio_text(b32_all, b32, "x"));
    }
}

// The engine and the limit timed in turn, window by window, in one benchmark (paired_bench.cpp):
// the ratio from the same moments of the machine.
void print_paired(const CollectingReporter& r, int all_threads) {
    auto name = [&](int steps, std::size_t n) { return paired_name(steps, n, all_threads); };
    bool any = false;
    for (int steps : {1, 32})
        for (std::size_t n : sizes) any = any || r.counter(name(steps, n), "engine/limit");
    if (!any) return;
    fmt::print("\n## Engine and limit timed in turn: gravity + quadratic drag + six walls\n\n");
    fmt::print("Each iteration runs the engine (Simulation::step_n) on one thread through {} steps from the initial "
               "particles, then the hand-fused limit through the same steps, the same number per call (the limit "
               "blocked like step_n when several) and the limit with the per-particle drag ledger every engine "
               "keeps (the room-contact issue's energy ledger; a bound on engine/limit for any engine that keeps "
               "it){}: all from the same moments of the machine.\n\n",
               steps_per_window,
               all_threads > 1 ? fmt::format(", then both again on {} threads", all_threads) : std::string());
    fmt::print("| n | steps per call | engine | limit | engine/limit | limit with drag ledger / limit |{}\n",
               all_threads > 1 ? fmt::format(" engine speed-up on {0} threads | limit speed-up on {0} threads |",
                                             all_threads)
                               : std::string());
    fmt::print("|---|---|---|---|---|---|{}\n", all_threads > 1 ? "---|---|" : "");
    for (int steps : {1, 32})
        for (std::size_t n : sizes) {
            const std::string b = name(steps, n);
            const auto ratio = r.counter(b, "engine/limit");
            if (!ratio) continue;
            fmt::print("| {} | {} | {} | {} | {:.2f} | {} |", size_label(n), steps,
                       rate_text(r.counter(b, "engine_rate")), rate_text(r.counter(b, "limit_rate")), *ratio,
                       ratio_text(r.counter(b, "ledger_limit/limit"), 1.0));
            if (all_threads > 1)
                fmt::print(" {} | {} |", speedup_text(r.counter(b, "engine_speedup")),
                           speedup_text(r.counter(b, "limit_speedup")));
            fmt::print("\n");
        }
}

// Where the engine's time goes beside the limit's: flight alone (no wall reached) and with the
// walls, and how far two threads get with the limit's own loop on the same thread pool.
void print_gap(const CollectingReporter& r, int all_threads) {
    bool any = false;
    for (std::size_t n : sizes) any = any || r.rate("kernel/drag_open/n:" + size_label(n) + "/threads:1");
    if (!any) return;
    fmt::print("\n## Where the gap to the limit is (particle-steps/s, 1 thread unless noted)\n\n");
    fmt::print("open room = no wall reached in the timed window: the vectorised flight phase alone.\n\n");
    fmt::print("| n | kernel, open room | limit, open room | ratio | kernel, walls | limit, walls | ratio | "
               "limit, {0} threads | limit speed-up | kernel, {0} threads | kernel speed-up |\n",
               all_threads);
    fmt::print("|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (std::size_t n : sizes) {
        const std::string size = size_label(n);
        const std::string all = "/threads:" + std::to_string(all_threads);
        const auto open = r.rate("kernel/drag_open/n:" + size + "/threads:1");
        const auto open_limit = r.rate("limit_hand_fused/drag_open/n:" + size);
        const auto walls = r.rate("kernel/drag_walls/n:" + size + "/threads:1");
        const auto walls_limit = r.rate("limit_hand_fused/drag_walls/n:" + size);
        const auto limit_all = all_threads > 1 ? r.rate("limit_hand_fused/drag_walls/n:" + size + all) : std::nullopt;
        const auto kernel_all = all_threads > 1 ? r.rate("kernel/drag_walls/n:" + size + all) : std::nullopt;
        if (!open && !walls) continue;
        fmt::print("| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n", size, rate_text(open),
                   rate_text(open_limit), ratio_text(open, open_limit), rate_text(walls), rate_text(walls_limit),
                   ratio_text(walls, walls_limit), rate_text(limit_all), ratio_text(limit_all, walls_limit, "x"),
                   rate_text(kernel_all), ratio_text(kernel_all, walls, "x"));
    }
}

// One row per name and size: the rate on one thread and on all of them, for the benchmarks
// named prefix + name + "/n:" + size + "/threads:" + threads.
void print_scaling(const CollectingReporter& r, int all_threads, const std::string& title, const char* column,
                   const std::string& prefix, const std::vector<std::string>& names) {
    auto base = [&](const std::string& name, std::size_t n) { return prefix + name + "/n:" + size_label(n) + "/threads:"; };
    bool any = false;
    for (const std::string& name : names)
        for (std::size_t n : sizes) any = any || r.rate(base(name, n) + "1");
    if (!any) return;
    fmt::print("\n## {}\n\n", title);
    fmt::print("| {} | n | 1 thread | {} threads | speed-up | ns/particle-step |\n", column, all_threads);
    fmt::print("|---|---|---|---|---|---|\n");
    for (const std::string& name : names)
        for (std::size_t n : sizes) {
            const auto one = r.rate(base(name, n) + "1");
            const auto all = all_threads > 1 ? r.rate(base(name, n) + std::to_string(all_threads)) : std::nullopt;
            if (!one && !all) continue;
            fmt::print("| {} | {} | {} | {} | {} | {} |\n", name, size_label(n), rate_text(one), rate_text(all),
                       ratio_text(all, one, "x"), one ? fmt::format("{:.2f}", 1e9 / *one) : "-");
        }
}

void print_methods(const CollectingReporter& r) {
    const char* methods[] = {"explicit_euler", "semi_implicit_euler", "velocity_verlet", "rk4", "dopri5",
                             "exponential"};
    const std::size_t counts[] = {1, 1000, 100000};
    bool any = false;
    for (const char* m : methods)
        for (std::size_t n : counts)
            any = any || r.rate(std::string("method/") + m + "/n:" + size_label(n) + "/threads:1");
    if (!any) return;
    fmt::print("\n## Integrators on gravity + quadratic drag + walls: cost per particle-step "
               "(ns, 1 thread) and relative to semi-implicit Euler\n\n");
    fmt::print("| method | n = 1 | n = 1k | n = 100k | ratio n = 1 | ratio n = 1k | ratio n = 100k |\n");
    fmt::print("|---|---|---|---|---|---|---|\n");
    for (const char* m : methods) {
        std::string cost[3], ratio[3];
        for (int k = 0; k < 3; ++k) {
            const std::string n = size_label(counts[k]);
            const auto rate = r.rate(std::string("method/") + m + "/n:" + n + "/threads:1");
            const auto euler = r.rate("method/semi_implicit_euler/n:" + n + "/threads:1");
            cost[k] = rate ? fmt::format("{:.1f}", 1e9 / *rate) : "-";
            ratio[k] = ratio_text(euler, rate);
        }
        fmt::print("| {} | {} | {} | {} | {} | {} | {} |\n", m, cost[0], cost[1], cost[2], ratio[0], ratio[1],
                   ratio[2]);
    }
}

void print_accuracy(const CollectingReporter& r) {
    const Measured* d6 = r.find("accuracy/dopri5/to:1e-6");
    const Measured* d9 = r.find("accuracy/dopri5/to:1e-9");
    const Measured* d2 = r.find("accuracy/dopri5/dt:2ms");
    const Measured* e2 = r.find("accuracy/semi_implicit_euler/dt:2ms");
    const Measured* e6 = r.find("accuracy/semi_implicit_euler/to:1e-6");
    if (!d6 && !d9 && !e2 && !e6) return;
    fmt::print("\n## Price of accuracy: 2 s drag trajectory, error of the end position against a tight "
               "reference\n\n");
    fmt::print("| run | setting | error (m) | force evaluations | wall time (us) | time / SIE at dt = 2 ms |\n");
    fmt::print("|---|---|---|---|---|---|\n");
    const double euler_time = e2 ? median(e2->seconds_per_run) : 0.0;
    auto row = [&](const char* label, const Measured* m, bool tolerance) {
        if (!m) return;
        const double t = median(m->seconds_per_run);
        const std::string setting = tolerance ? fmt::format("rtol = atol = {:.2g}", counter(*m, "tol").value())
                                              : fmt::format("dt = {:.3g} s", counter(*m, "dt_s").value());
        fmt::print("| {} | {} | {:.2g} | {:.0f} | {:.1f} | {} |\n", label, setting, counter(*m, "error_m").value(),
                   counter(*m, "force_evals").value(), 1e6 * t,
                   euler_time > 0 ? fmt::format("{:.2f}", t / euler_time) : "-");
    };
    row("semi-implicit Euler, default dt", e2, false);
    row("semi-implicit Euler to 1e-6 m", e6, false);
    row("dopri5 to 1e-6 m", d6, true);
    row("dopri5 to 1e-9 m", d9, true);
    row("dopri5 inside the default 2 ms steps", d2, true);
    if (e6 && d6)
        fmt::print("\nTo reach 1e-6 m, semi-implicit Euler costs {:.0f}x what adaptive Dormand-Prince costs.\n",
                   median(e6->seconds_per_run) / median(d6->seconds_per_run));
    if (e6 && d9) {
        // First order: 1000x less error needs 1000x the steps.
        const double euler_9 = 1000.0 * median(e6->seconds_per_run);
        fmt::print("To reach 1e-9 m it would need about {:.3g} s (extrapolated: error ~ dt), {:.0f}x dopri5's "
                   "cost.\n",
                   euler_9, euler_9 / median(d9->seconds_per_run));
    }
}

}  // namespace

}  // namespace pl::bench

int main(int argc, char** argv) {
    using namespace pl::bench;
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
    register_engine_benchmarks();
    register_limit_benchmarks();
    register_paired_benchmarks();
    register_baseline_benchmarks();
    register_method_benchmarks();
    register_accuracy_benchmarks();
    register_collision_benchmarks();
    register_collision_paired_benchmarks();
    CollectingReporter reporter;
    benchmark::RunSpecifiedBenchmarks(&reporter);
    const int all_threads = pl::hardware_threads();
    print_comparison(reporter, all_threads);
    print_steps(reporter, all_threads);
    print_paired(reporter, all_threads);
    print_gap(reporter, all_threads);
    print_scaling(reporter, all_threads, "Engine by workload (particle-steps/s; ns per particle-step, 1 thread)",
                  "workload", "engine/", {"gravity", "drag_walls", "drag_walls_shear", "drag_rest"});
    print_methods(reporter);
    print_scaling(reporter, all_threads,
                  "Integrators by size (gravity + quadratic drag + walls; particle-steps/s; ns per particle-step, "
                  "1 thread)",
                  "method", "method/", {"explicit_euler", "semi_implicit_euler", "velocity_verlet", "rk4", "dopri5",
                                        "exponential"});
    print_accuracy(reporter);
    benchmark::Shutdown();
    return 0;
}
