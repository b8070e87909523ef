// SIGINT, SIGTERM and SIGHUP while a command writes files: instead of dying mid-row, the
// command finishes the row it is writing, removes its temporary files (the targets keep their
// old contents) and exits 128 + the signal number, as a shell expects.
#pragma once

namespace pl::cli {

class InterruptGuard {
public:
    InterruptGuard();   // installs the handlers
    ~InterruptGuard();  // restores the previous ones
    InterruptGuard(const InterruptGuard&) = delete;
    InterruptGuard& operator=(const InterruptGuard&) = delete;

    // The signal received since construction, or 0.
    static int received();
};

// "SIGINT", "SIGTERM", "SIGHUP".
const char* signal_name(int signal);

}  // namespace pl::cli
