// The state the GUI tests read: a JSON snapshot written at exit and on SIGUSR1.
#pragma once

#include "ui/lab_session.hpp"

#include <filesystem>
#include <string>

namespace pl::app {

// Written to a temporary file and renamed, so a reader never sees half a dump.
// Returns an empty string on success, otherwise why it failed.
std::string write_state_dump(const std::filesystem::path& file, const ui::LabSession& session, long frames);

}  // namespace pl::app
