// particle-lab sweep: a study over preset fields (grid axes and seeded random samples), one row
// per scene, variant and metric; sharded with --shard I/N, resumable with --resume.
#include "cli/cli_support.hpp"
#include "cli/sweep_commands.hpp"

#include "io/preset_io.hpp"
#include "io/sweep_table.hpp"

#include <fmt/format.h>

#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <mutex>
#include <sstream>

namespace pl::cli {

namespace {

struct SweepCliOptions {
    std::string preset;
    std::vector<std::string> axes, samples;
    std::size_t sample_count = 0;
    std::uint64_t seed = 1;
    std::string metrics;
    double duration_s = 5.0;
    std::size_t particle = 0;
    std::string out;
    bool json = false;
    std::string shard;
    bool strided = false;
    bool resume = false;
    int threads = 0;
};

// Points done, rate and time left on stderr, only when it is a terminal; at most 5 redraws/s.
class SweepProgress {
public:
    SweepProgress() : enabled_(isatty(STDERR_FILENO) == 1) {}
    ~SweepProgress() {
        if (drawn_) std::fprintf(stderr, "\r%-70s\r", "");
    }
    void update(std::size_t done, std::size_t total) {
        if (!enabled_) return;
        const std::lock_guard lock(mutex_);
        const auto now = clock::now();
        if (done < total && now - last_ < std::chrono::milliseconds(200)) return;
        last_ = now;
        const double seconds = std::chrono::duration<double>(now - start_).count();
        const double rate = seconds > 0.0 ? static_cast<double>(done) / seconds : 0.0;
        const double left = rate > 0.0 ? static_cast<double>(total - done) / rate : 0.0;
        std::fprintf(stderr, "\rsweep: %zu/%zu points, %.1f points/s, %.0f s left   ", done, total, rate, left);
        std::fflush(stderr);
        drawn_ = true;
    }

private:
    using clock = std::chrono::steady_clock;
    bool enabled_;
    bool drawn_ = false;
    std::mutex mutex_;
    clock::time_point start_ = clock::now(), last_{};
};

std::optional<std::string> read_text(const std::string& path) {
    std::error_code ec;
    const auto size = std::filesystem::file_size(path, ec);
    if (ec) {
        print_error("sweep", fmt::format("{}: cannot read it ({})", path, ec.message()));
        return std::nullopt;
    }
    if (size > max_preset_file_bytes) {
        print_error("sweep", fmt::format("{}: {} bytes, more than the {} a preset may have", path, size, max_preset_file_bytes));
        return std::nullopt;
    }
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    if (!in) {
        print_error("sweep", fmt::format("{}: cannot read it", path));
        return std::nullopt;
    }
    return text.str();
}

// The plan and the spec from the options; an error text (exit 2) or "".
std::string build_spec(const SweepCliOptions& o, const std::string& preset_text, SweepSpec& spec) {
    spec.preset_text = preset_text;
    spec.duration_s = o.duration_s;
    spec.particle = o.particle;
    for (const std::string& a : o.axes)
        if (std::string e = parse_axis(a, spec.plan.axes.emplace_back()); !e.empty()) return e;
    for (const std::string& s : o.samples)
        if (std::string e = parse_sample(s, spec.plan.samples.emplace_back()); !e.empty()) return e;
    if (spec.plan.axes.empty() && spec.plan.samples.empty()) return "give at least one --axis or --sample";
    if (!spec.plan.samples.empty() && o.sample_count == 0) return "--sample needs --samples N (N >= 1)";
    if (spec.plan.samples.empty() && o.sample_count > 0) return "--samples needs at least one --sample";
    spec.plan.sample_count = o.sample_count;
    spec.plan.seed = o.seed;
    if (o.metrics.empty()) {
        for (std::size_t m = 0; m < sweep_metrics().size(); ++m) spec.metrics.push_back(m);
        return "";
    }
    return parse_metric_list(o.metrics, spec.metrics);
}

enum class Resume { run, done, refuse };

// --resume: done when `out` already holds this slice of this sweep, complete; refuse when it
// holds another sweep's results (not overwritten: a wrong --out would lose finished work).
Resume resume_state(const std::string& out, const SweepHeader& header) {
    if (!std::filesystem::exists(out)) return Resume::run;
    std::string error;
    const std::optional<SweepFile> f = read_sweep_file(out, error);
    if (!f) {
        print_error("sweep", fmt::format("--resume: {}; running it again", error));
        return Resume::run;
    }
    const Shard& s = f->header.shard;
    if (f->header.id == header.id && f->header.points == header.points && s.index == header.shard.index &&
        s.count == header.shard.count && s.strided == header.shard.strided)
        return Resume::done;
    print_error("sweep", fmt::format("--resume: {} holds shard {}/{} of sweep {}, not shard {}/{} of this sweep ({}); "
                                     "remove it or choose another --out",
                                     out, s.index, s.count, f->header.id, header.shard.index, header.shard.count,
                                     header.id));
    return Resume::refuse;
}

int sweep(const SweepCliOptions& o) {
    const std::optional<std::string> preset_text = read_text(o.preset);
    if (!preset_text) return exit_bad_input;
    SweepSpec spec;
    SweepHeader header;
    std::string error = build_spec(o, *preset_text, spec);
    if (error.empty() && !o.shard.empty()) error = parse_shard(o.shard, o.strided, header.shard);
    if (error.empty() && o.strided && o.shard.empty()) error = "--strided needs --shard I/N";
    if (error.empty() && o.json && !header.shard.whole()) error = "--json: shards are CSV (sweep-merge joins them)";
    if (error.empty() && o.resume && o.out.empty()) error = "--resume needs --out FILE (the output it looks for)";
    if (!error.empty()) {
        print_error("sweep", error);
        return exit_bad_input;
    }
    header.id = sweep_id(spec);
    header.points = spec.plan.point_count();
    const Resume resume = o.resume ? resume_state(o.out, header) : Resume::run;
    if (resume == Resume::refuse) return exit_bad_input;
    if (resume == Resume::done) {
        std::fprintf(stderr, "particle-lab sweep: %s already holds shard %zu/%zu of sweep %s: not run again\n",
                     o.out.c_str(), header.shard.index, header.shard.count, header.id.c_str());
        return exit_ok;
    }
    const PreparedSweep prepared = prepare_sweep(spec, shard_points(header.shard, header.points));
    if (!prepared.error.empty()) {
        print_error("sweep", fmt::format("{}: {}", o.preset, prepared.error));
        return exit_bad_input;
    }
    SweepProgress progress;
    SweepRunOptions options;
    options.threads = o.threads;
    options.progress = [&](std::size_t done, std::size_t total) { progress.update(done, total); };
    const SweepResults results = run_sweep(prepared, spec.duration_s, options);
    const std::string text = o.json ? sweep_json(header, spec, prepared, results) : sweep_csv(header, spec, prepared, results);
    return write_sweep_output("sweep", o.out, text);
}

std::string metrics_footer() {
    std::string text = "Metrics (default: all), per scene, variant and the --particle:\n";
    for (const SweepMetric& m : sweep_metrics()) text += fmt::format("  {:<24} {}\n", m.name, m.meaning);
    return text;
}

}  // namespace

int write_sweep_output(const std::string& command, const std::string& out, const std::string& text) {
    if (out.empty()) {
        std::cout << text << std::flush;
        if (std::cout) return exit_ok;
        print_error(command, "writing to stdout failed");
        return exit_runtime_failure;
    }
    if (std::string e = write_file_atomically(out, text); !e.empty()) {
        print_error(command, e);
        return exit_runtime_failure;
    }
    return exit_ok;
}

void add_sweep_command(CLI::App& app, int& exit_code) {
    auto o = std::make_shared<SweepCliOptions>();
    CLI::App* cmd = app.add_subcommand("sweep", "a study over preset fields: one row per scene, variant and metric");
    cmd->footer(
        "Axes are preset paths, as for --set (drag.cd, particles[0].mass, variants[1].drag.model), plus\n"
        "launch.speed_mps and launch.elevation_deg, which set particles[0].velocity (its horizontal\n"
        "direction kept). Every point is checked before any runs. Points are numbered with the first axis\n"
        "varying slowest, the samples fastest; sample k depends on (seed, k) only. Output: CSV with two\n"
        "header lines naming the sweep and the slice, then point,AXES...,variant,metric,value.\n\n" +
        metrics_footer());
    cmd->add_option("PRESET", o->preset, "preset JSON file")->required();
    cmd->add_option("--axis", o->axes, "PATH=LOW:HIGH:COUNT or PATH=V1,V2,... (repeatable)");
    cmd->add_option("--sample", o->samples, "PATH=normal(MEAN,SD) or PATH=uniform(LOW,HIGH) (repeatable)");
    cmd->add_option("--samples", o->sample_count, "random samples per grid point");
    cmd->add_option("--seed", o->seed, "seed of the samples")->capture_default_str();
    cmd->add_option("--metrics", o->metrics, "comma-separated metric names (see below)");
    cmd->add_option("--duration", o->duration_s, "simulated seconds per scene")->capture_default_str()->check(positive_number());
    cmd->add_option("--particle", o->particle, "particle whose metrics are reported")->capture_default_str();
    cmd->add_option("--out", o->out, "output file, written atomically (default: stdout)");
    cmd->add_flag("--json", o->json, "JSON instead of CSV (whole runs only)");
    cmd->add_option("--shard", o->shard, "I/N: run the I-th of N slices (0-based)");
    cmd->add_flag("--strided", o->strided, "slices take every N-th point instead of contiguous blocks");
    cmd->add_flag("--resume", o->resume, "skip when --out already holds this slice, complete");
    cmd->add_option("--threads", o->threads, "scenes run at once (0: one per hardware thread)")->capture_default_str();
    cmd->callback([o, &exit_code] { exit_code = sweep(*o); });
}

}  // namespace pl::cli
