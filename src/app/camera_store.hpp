// Remembers the camera between runs in a small text file in the user's config directory.
#pragma once

#include "app/camera.hpp"

#include <filesystem>
#include <optional>

namespace pl::app {

// The camera saved for a room of the same size, if the file exists and is intact. A camera
// saved for a different room is not reused: it would frame the wrong space.
std::optional<OrbitCamera> load_camera(const std::filesystem::path& file, const Room& room);
void save_camera(const std::filesystem::path& file, const OrbitCamera& camera, const Room& room);

}  // namespace pl::app
