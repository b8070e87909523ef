#include "app/signals.hpp"

#include <csignal>

namespace pl::app {

namespace {

volatile std::sig_atomic_t quit_flag = 0;
volatile std::sig_atomic_t dump_flag = 0;

void on_quit_signal(int) { quit_flag = 1; }
void on_dump_signal(int) { dump_flag = 1; }

}  // namespace

void install_signal_handlers() {
    std::signal(SIGTERM, on_quit_signal);
    std::signal(SIGINT, on_quit_signal);
    std::signal(SIGUSR1, on_dump_signal);
}

bool quit_signalled() { return quit_flag != 0; }

bool take_dump_request() {
    if (dump_flag == 0) return false;
    dump_flag = 0;
    return true;
}

}  // namespace pl::app
