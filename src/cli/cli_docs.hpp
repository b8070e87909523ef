// Documents derived from the CLI11 definitions themselves, so that they cannot drift from the
// options the program accepts: a bash completion script (installed) and docs/cli.md (checked
// by a test against this output).
#pragma once

#include <CLI/CLI.hpp>

#include <string>

namespace pl::cli {

// A bash completion function for `particle-lab`: the commands, each command's flags, and file
// names after an option that takes a value and for PRESET.
std::string bash_completion(const CLI::App& app);

// docs/cli.md: the synopsis, then every command with its --help text.
std::string markdown_reference(const CLI::App& app);

}  // namespace pl::cli
