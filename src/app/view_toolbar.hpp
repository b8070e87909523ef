// The strip above the 3D view: what the view shows (trails, velocity and wind arrows, split
// panes) and where it looks from.
#pragma once

#include "app/record_controls.hpp"
#include "app/shortcuts.hpp"
#include "ui/lab_session.hpp"

namespace pl::app {

// Contents only (inside a window the shell created); returns the camera commands clicked.
ViewCommand draw_view_toolbar(ui::LabSession& session, RecordControl& record);

}  // namespace pl::app
