#include "cli/interrupt.hpp"

#include <array>
#include <csignal>

namespace pl::cli {

namespace {

volatile std::sig_atomic_t received_signal = 0;
constexpr std::array handled{SIGINT, SIGTERM, SIGHUP};
std::array<struct sigaction, handled.size()> previous{};

extern "C" void on_signal(int signal) { received_signal = signal; }

}  // namespace

InterruptGuard::InterruptGuard() {
    received_signal = 0;
    struct sigaction action {};
    action.sa_handler = on_signal;
    sigemptyset(&action.sa_mask);
    for (std::size_t i = 0; i < handled.size(); ++i) sigaction(handled[i], &action, &previous[i]);
}

InterruptGuard::~InterruptGuard() {
    for (std::size_t i = 0; i < handled.size(); ++i) sigaction(handled[i], &previous[i], nullptr);
}

int InterruptGuard::received() { return received_signal; }

const char* signal_name(int signal) {
    switch (signal) {
        case SIGINT: return "SIGINT";
        case SIGTERM: return "SIGTERM";
        case SIGHUP: return "SIGHUP";
        default: return "a signal";
    }
}

}  // namespace pl::cli
