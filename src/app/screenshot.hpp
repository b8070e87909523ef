// PNG of the whole window as drawn this frame (3D view and panels).
#pragma once

#include <filesystem>
#include <string>

namespace pl::app {

// Reads the back buffer (call after drawing, before swapping). Returns "" or why it failed.
std::string write_screenshot_png(const std::filesystem::path& file, int framebuffer_width, int framebuffer_height);

}  // namespace pl::app
