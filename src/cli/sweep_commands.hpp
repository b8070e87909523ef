// particle-lab sweep (a study over preset fields, sharded) and sweep-merge (joins the shards).
#pragma once

#include <CLI/CLI.hpp>

namespace pl::cli {

void add_sweep_command(CLI::App& app, int& exit_code);
void add_sweep_merge_command(CLI::App& app, int& exit_code);

}  // namespace pl::cli
