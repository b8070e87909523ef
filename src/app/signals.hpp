// POSIX signals the GUI answers: SIGTERM/SIGINT end the run cleanly (state dump, camera saved),
// SIGUSR1 writes the state dump now (tests read the state of a running app this way).
#pragma once

namespace pl::app {

void install_signal_handlers();
bool quit_signalled();
bool take_dump_request();  // true once per SIGUSR1

}  // namespace pl::app
