// Shared plumbing of the headless commands: loading presets, exit codes, plain-text tables and
// number formatting (progress on a terminal: cli/progress.hpp).
#pragma once

#include "cli/progress.hpp"
#include "physics/model/scene.hpp"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <optional>
#include <string>
#include <vector>

namespace pl::cli {

enum ExitCode : int { exit_ok = 0, exit_runtime_failure = 1, exit_bad_input = 2 };

// Each command adds itself to the app; its callback stores its exit code in `exit_code`.
void add_run_command(CLI::App& app, int& exit_code);
void add_validate_command(CLI::App& app, int& exit_code);
void add_schema_command(CLI::App& app, int& exit_code);
void add_compare_command(CLI::App& app, int& exit_code);
void add_accuracy_command(CLI::App& app, int& exit_code);
void add_stability_command(CLI::App& app, int& exit_code);
void add_advise_command(CLI::App& app, int& exit_code);
void add_bench_command(CLI::App& app, int& exit_code);

// Loads and validates a preset ("-": standard input) with the --set overrides applied to its
// document first (io/preset_overrides.hpp); on failure prints every error to stderr, prefixed by
// the command name, and returns nothing (the caller exits with exit_bad_input).
std::optional<Scene> load_scene(const std::string& command, const std::string& path,
                                const std::vector<std::string>& sets = {});

// The options every command that reads a preset shares: --set KEY=VALUE (repeatable).
void add_set_option(CLI::App* command, std::vector<std::string>& sets);

// -q,--quiet: no progress and no warnings on stderr (cli/progress.hpp).
void add_quiet_flag(CLI::App* command);

// Adds --max-preset-bytes (the file-size limit load_scene applies) to a command reading a preset.
void add_max_preset_bytes_option(CLI::App& command);

// Prints "particle-lab COMMAND: MESSAGE" to stderr.
void print_error(const std::string& command, const std::string& message);

// `text` safe to print on a terminal: control characters written as \x1b or \u009b.
std::string printable(const std::string& text);

// A variant's name for tables and CSV: its label, or its index when the scene has no variants
// (or the label is empty).
std::string variant_name(const Scene& scene, std::size_t variant);
// For CSV and JSON: the label exactly as the preset gives it ("" when it gives none), always
// written beside the variant's index, so that a label "1" and variant 1 cannot be confused.
std::string variant_label(const Scene& scene, std::size_t variant);

// Left-aligned first column, right-aligned others; columns sized to their widest cell.
struct Table {
    std::vector<std::string> header;
    std::vector<std::vector<std::string>> rows;
    void print(std::FILE* out = stdout) const;
};

// Compact human formats for tables (CSV and JSON keep full precision).
std::string sig(double value, int digits = 4);        // "0.1235", "1.2e-07", "-"/"inf" for non-finite
std::string sig(const std::optional<double>& value, int digits = 4);  // "-" when empty

// Option checks with messages that state the rule ("must be a number > 0, got 'abc'").
CLI::Validator positive_number();
CLI::Validator positive_integer();
CLI::Validator whole_number_at_least(unsigned long long least);

// A variant given by label or by index; empty when there is none such.
std::optional<std::size_t> find_variant(const Scene& scene, const std::string& label_or_index);
// "'a', 'b', 'c'": the variant names, for error messages.
std::string variant_list(const Scene& scene);

// Parses a comma-separated list of doubles / method names; returns an error text naming the
// option and the bad item, or empty.
std::string parse_double_list(const std::string& option, const std::string& text, std::vector<double>& out);
std::string parse_method_list(const std::string& option, const std::string& text, std::vector<Method>& out);

}  // namespace pl::cli
