// Refuses a headless run that cannot fit in the memory the machine has, or would take more than
// a day, with the numbers; warns about runs over a minute. The estimate itself is shared with the
// GUI: physics/studies/resource_estimate.hpp.
#pragma once

#include "physics/studies/resource_estimate.hpp"

#include <string>

namespace pl::cli {

// Empty when the work may run; else the refusal, with the numbers. Prints the warning for
// long runs to stderr, prefixed by the command.
std::string check_work(const std::string& command, const WorkEstimate& w);

}  // namespace pl::cli
