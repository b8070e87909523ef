#include "app/app.hpp"

#include <cstdio>

namespace pl::app {

int run_gui(int, char**) {
    std::fprintf(stderr, "GUI not yet\n");
    return 1;
}

}  // namespace pl::app
