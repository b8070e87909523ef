// The GUI's frame loop: window, input, physics stepping, panels, 3D view, screenshots and the
// state dump, until the user quits or --frames runs out.
#pragma once

#include "app/gui_options.hpp"
#include "ui/lab_session.hpp"

namespace pl::app {

// Returns the process exit code. Throws std::runtime_error when the window or the GL resources
// cannot be created.
int run_frame_loop(ui::LabSession& session, const GuiOptions& options);

}  // namespace pl::app
