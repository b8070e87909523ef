// The state the GUI tests read: a JSON snapshot written at exit and on SIGUSR1.
#pragma once

#include "app/camera.hpp"
#include "app/launch_gesture.hpp"
#include "app/record_controls.hpp"
#include "app/view_panes.hpp"
#include "ui/lab_session.hpp"

#include <filesystem>
#include <string>

namespace pl::app {

// What the 3D view showed: the camera, the panes it drew (tests click particles through it) and
// a launch being aimed; and the recorder's state.
struct ViewSnapshot {
    OrbitCamera camera;
    std::vector<ViewPane> panes;
    LaunchAim aim;
    const RecordControl* record = nullptr;
};

// Written to a temporary file and renamed, so a reader never sees half a dump.
// Returns an empty string on success, otherwise why it failed.
std::string write_state_dump(const std::filesystem::path& file, const ui::LabSession& session, long frames,
                             const ViewSnapshot& view);

}  // namespace pl::app
