// The GUI shell: window, GL loader, frame loop.
#pragma once

namespace pl::app {

int run_gui(int argc, char** argv);

}  // namespace pl::app
