#include "cli/run_outputs.hpp"

#include "cli/cli_support.hpp"
#include "cli/trajectory_options.hpp"
#include "io/npy_writer.hpp"

#include <fmt/format.h>

namespace pl::cli {

namespace {

bool ends_with(const std::string& text, const std::string& suffix) {
    return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

int RunOutputs::open(const RunOutputSpec& spec, std::size_t particles, std::uint64_t base_steps, std::size_t variants) {
    spec_ = spec;
    if (spec.out == "-" && spec.events == "-") {
        print_error("run", "--out and --events cannot both be standard output ('-')");
        return exit_bad_input;
    }
    if (!spec.particles.empty()) {
        const std::string error = parse_particle_list(spec.particles, particles, particles_);
        if (!error.empty()) {
            print_error("run", error);
            return exit_bad_input;
        }
    }
    selected_.assign(particles, particles_.empty() ? 1 : 0);
    for (std::size_t i : particles_) selected_[i] = 1;
    if (!spec.out.empty()) {
        if (!out_.open(spec.out)) {
            print_error("run", "--out: " + out_.error());
            return exit_runtime_failure;
        }
        const bool npy = ends_with(spec.out, ".npy");
        sink_ = npy ? make_npy_trajectory_sink(out_.stream()) : make_csv_trajectory_sink(out_.stream());
        const std::uint64_t written = particles_.empty() ? particles : particles_.size();
        const std::string warning =
            trajectory_size_warning(spec.out, trajectory_rows_bound(base_steps, spec.every, written, variants) * sink_->row_bytes());
        if (!warning.empty() && !quiet()) std::fprintf(stderr, "particle-lab run: warning: %s\n", warning.c_str());
    }
    if (!spec.events.empty()) {
        if (!events_out_.open(spec.events)) {
            print_error("run", "--events: " + events_out_.error());
            return exit_runtime_failure;
        }
        events_out_.stream() << event_columns << '\n';
        events_csv_ = std::make_unique<CsvWriter>(events_out_.stream());
    }
    return exit_ok;
}

void RunOutputs::write_states(const Simulation& sim, const std::string& label, std::size_t variant) {
    for (std::size_t i = 0; i < sim.particle_count(); ++i)
        if (selected_[i]) sink_->write(state_row(sim, variant, i), label);
}

// Event times are the located times of impact inside a step, so events carry t_s, not a step.
void RunOutputs::write_events(const std::vector<Event>& events, const std::string& label, std::size_t variant) {
    CsvWriter& csv = *events_csv_;
    for (const Event& e : events) {
        if (!selected_[e.particle]) continue;
        csv.field(e.t).field(label).field(static_cast<std::uint64_t>(variant)).field(static_cast<std::uint64_t>(e.particle));
        csv.field(e.wall >= 0 ? wall_name(e.wall) : "");
        csv.field(e.speed_in).field(e.speed_out).field(to_string(e.kind));
        csv.end_row();
    }
}

int RunOutputs::close() {
    int code = exit_ok;
    if (sink_ && (!sink_->finish() || !out_.close())) {
        print_error("run", "--out: " + out_.error());
        code = exit_runtime_failure;
    }
    if (events_csv_ && !events_out_.close()) {
        print_error("run", "--events: " + events_out_.error());
        code = exit_runtime_failure;
    }
    return code;
}

}  // namespace pl::cli
