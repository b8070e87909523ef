#include "cli/commands.hpp"

#include "cli/cli_docs.hpp"
#include "cli/cli_support.hpp"
#include "cli/sweep_commands.hpp"

#include <CLI/CLI.hpp>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <iostream>

namespace pl::cli {

namespace {

constexpr const char* commands[] = {"run",    "validate", "schema", "compare", "accuracy",
                                    "stability", "advise", "bench", "sweep", "sweep-merge"};

constexpr const char* description =
    "particle-lab: a lab for Newtonian particle experiments (gravity, air drag, wind, bouncing in a room).\n"
    "Without a command it opens the GUI:  particle-lab [PRESET]  (default presets/default.json).\n"
    "Commands run headless. Exit codes: 0 ok, 1 runtime failure, 2 bad input.";

// A command whose report could not be written (a full disk, a closed pipe) has failed even if
// its work succeeded: exit 1 with a message instead of 0.
int stdout_written(int exit_code) {
    std::cout.flush();
    errno = 0;
    const bool flushed = std::fflush(stdout) == 0 && std::cout.good();
    if (flushed && std::ferror(stdout) == 0) return exit_code;
    // The reason is known only when the final flush failed; an earlier failed write left no errno.
    std::fprintf(stderr, "particle-lab: cannot write the standard output%s%s\n", errno != 0 ? ": " : "",
                 errno != 0 ? std::strerror(errno) : "");
    return exit_code == exit_ok ? exit_runtime_failure : exit_code;
}

}  // namespace

bool is_subcommand(int argc, char** argv) {
    if (argc < 2) return false;
    for (const char* c : commands)
        if (std::strcmp(argv[1], c) == 0) return true;
    for (const char* flag : {"--help", "-h", "help", "--version", "--bash-completion", "--markdown-help"})
        if (std::strcmp(argv[1], flag) == 0) return true;
    return false;
}

int run_command(int argc, char** argv) {
    CLI::App app(description, "particle-lab");
    app.require_subcommand(1);
    app.fallthrough(false);
    app.get_formatter()->column_width(30);
    app.footer("Run 'particle-lab COMMAND --help' for the options of a command.");
    app.set_version_flag("--version", std::string("particle-lab ") + PL_VERSION, "print the version and exit");
    int exit_code = exit_ok;
    add_run_command(app, exit_code);
    add_validate_command(app, exit_code);
    add_schema_command(app, exit_code);
    add_compare_command(app, exit_code);
    add_accuracy_command(app, exit_code);
    add_stability_command(app, exit_code);
    add_advise_command(app, exit_code);
    add_bench_command(app, exit_code);
    add_sweep_command(app, exit_code);
    add_sweep_merge_command(app, exit_code);
    for (CLI::App* command : app.get_subcommands({}))
        if (command->get_option_no_throw("PRESET") != nullptr) add_max_preset_bytes_option(*command);
    if (argc >= 2 && std::strcmp(argv[1], "help") == 0) {
        std::cout << app.help();
        return exit_ok;
    }
    // Documents generated from the definitions above (installed completion, docs/cli.md).
    if (argc == 2 && std::strcmp(argv[1], "--bash-completion") == 0) {
        std::cout << bash_completion(app);
        return exit_ok;
    }
    if (argc == 2 && std::strcmp(argv[1], "--markdown-help") == 0) {
        std::cout << markdown_reference(app);
        return exit_ok;
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e) == 0 ? exit_ok : exit_bad_input;
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e) == 0 ? exit_ok : exit_bad_input;
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e) == 0 ? exit_ok : exit_bad_input;
    } catch (const CLI::ParseError& e) {
        const std::string sub = app.get_subcommands().empty() ? "" : app.get_subcommands().front()->get_name();
        std::fprintf(stderr, "particle-lab%s%s: %s\nRun 'particle-lab %s%s--help' for the options.\n",
                     sub.empty() ? "" : " ", sub.c_str(), e.what(), sub.c_str(), sub.empty() ? "" : " ");
        return exit_bad_input;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "particle-lab: runtime failure: %s\n", e.what());
        return exit_runtime_failure;
    }
    return stdout_written(exit_code);
}

}  // namespace pl::cli
