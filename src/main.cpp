// particle-lab: with no subcommand opens the GUI; subcommands run headless (see src/cli).
#include "cli/commands.hpp"

#if PL_HAS_GUI
#include "app/app.hpp"
#endif

#include <cstdio>
#include <string>

int main(int argc, char** argv) {
    if (pl::cli::is_subcommand(argc, argv)) return pl::cli::run_command(argc, argv);
#if PL_HAS_GUI
    return pl::app::run_gui(argc, argv);
#else
    std::fprintf(stderr, "particle-lab: built without the GUI; use a subcommand (run, validate, ...)\n");
    return 2;
#endif
}
