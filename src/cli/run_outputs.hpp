// The files `run` writes: the trajectory (CSV, or .npy when the name ends in .npy) and the events
// CSV, each a file or standard output ("-"), filtered to --particles, with a warning before the
// run when the trajectory would be very large.
#pragma once

#include "cli/output_stream.hpp"
#include "io/csv_writer.hpp"
#include "io/trajectory_table.hpp"
#include "physics/stepping/events.hpp"
#include "physics/stepping/simulation.hpp"

#include <memory>
#include <string>
#include <vector>

namespace pl::cli {

struct RunOutputSpec {
    std::string out, events;  // paths; "" = not written, "-" = standard output
    std::string particles;    // --particles LIST; "" = all
    std::uint64_t every = 1;
};

// The events CSV's header.
constexpr const char* event_columns = "t_s,variant,variant_index,particle,wall,speed_in_m_s,speed_out_m_s,kind";

class RunOutputs {
public:
    // Opens the outputs; on failure prints why and returns the exit code (else exit_ok).
    int open(const RunOutputSpec& spec, std::size_t particles, std::uint64_t base_steps, std::size_t variants);
    bool trajectory() const { return sink_ != nullptr; }
    bool events() const { return events_csv_ != nullptr; }
    bool to_stdout() const { return out_.is_stdout() || events_out_.is_stdout(); }
    void write_states(const Simulation& sim, const std::string& label, std::size_t variant);
    void write_events(const std::vector<Event>& events, const std::string& label, std::size_t variant);
    // Completes and closes both; on failure prints why and returns exit_runtime_failure.
    int close();

private:
    RunOutputSpec spec_;
    OutputStream out_, events_out_;
    std::unique_ptr<TrajectorySink> sink_;
    std::unique_ptr<CsvWriter> events_csv_;
    std::vector<std::size_t> particles_;  // the filter; empty = every particle
    std::vector<char> selected_;          // per particle: written or not
};

}  // namespace pl::cli
