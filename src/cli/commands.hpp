// Headless command line: run, validate, compare, accuracy, stability, advise, bench, sweep,
// sweep-merge.
// Exit codes: 0 ok, 1 runtime failure, 2 bad input.
#pragma once

namespace pl::cli {

bool is_subcommand(int argc, char** argv);
int run_command(int argc, char** argv);

}  // namespace pl::cli
