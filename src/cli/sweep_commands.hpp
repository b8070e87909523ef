// particle-lab sweep (a study over preset fields, sharded) and sweep-merge (joins the shards).
#pragma once

#include <CLI/CLI.hpp>

#include <string>

namespace pl::cli {

void add_sweep_command(CLI::App& app, int& exit_code);
void add_sweep_merge_command(CLI::App& app, int& exit_code);

// Writes a sweep's output to stdout (`out` empty) or atomically to the file `out`; returns the
// exit code (1 when the write failed, with the reason on stderr).
int write_sweep_output(const std::string& command, const std::string& out, const std::string& text);

}  // namespace pl::cli
