#include "cli/commands.hpp"

#include <cstdio>
#include <cstring>

namespace pl::cli {

bool is_subcommand(int argc, char** argv) {
    return argc > 1 && std::strcmp(argv[1], "run") == 0;
}

int run_command(int, char**) {
    std::fprintf(stderr, "not yet\n");
    return 1;
}

}  // namespace pl::cli
