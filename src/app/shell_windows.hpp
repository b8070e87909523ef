// The fixed-position windows of the layout, each filled by its panel from ui/.
#pragma once

#include "app/layout.hpp"
#include "app/record_controls.hpp"
#include "app/shortcuts.hpp"
#include "ui/lab_session.hpp"

namespace pl::app {

// Heights of title bars, toolbar and status bar for the current font and style.
LayoutMetrics layout_metrics();

// Draws every panel window at its place; records which panels the user collapsed (they take
// effect in the next frame's layout). Returns the camera commands from the view toolbar.
ViewCommand draw_shell_windows(ui::LabSession& session, const ShellLayout& layout, PanelCollapse& collapsed,
                               RecordControl& record);

}  // namespace pl::app
