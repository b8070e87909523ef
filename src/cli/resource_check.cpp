#include "cli/resource_check.hpp"

#include "cli/cli_support.hpp"

#include <fmt/format.h>

namespace pl::cli {

namespace {

constexpr double warn_after_s = 60.0;
constexpr double refuse_after_s = 86400.0;

}  // namespace

std::string check_work(const std::string& command, const WorkEstimate& w) {
    if (std::string refused = memory_refusal(w); !refused.empty()) return refused;
    const double seconds = estimated_seconds(w);
    if (!(seconds <= refuse_after_s))
        return fmt::format("would take at least {} ({:.3g} steps x {}); the limit is a day: use a shorter --duration or "
                           "a larger dt",
                           duration_text(seconds), w.steps, counts_text(w));
    if (seconds > warn_after_s)
        print_error(command, fmt::format("warning: this will take at least {} ({:.3g} steps x {})",
                                         duration_text(seconds), w.steps, counts_text(w)));
    return "";
}

}  // namespace pl::cli
