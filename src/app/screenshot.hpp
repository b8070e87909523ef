// PNG of the whole window as drawn this frame (3D view and panels).
#pragma once

#include <filesystem>
#include <string>

namespace pl::app {

// A rectangle of the framebuffer in pixels, origin top left.
struct PixelRect {
    int x = 0, y = 0, w = 0, h = 0;
};

// A rectangle in ImGui display coordinates as framebuffer pixels (`sx`, `sy`: framebuffer pixels
// per display unit, e.g. 2 on a HiDPI screen).
PixelRect to_pixels(float x, float y, float w, float h, float sx, float sy);

// Reads `area` of the back buffer (call after drawing, before swapping) into a PNG; the area is
// clipped to the framebuffer. Returns "" or why it failed.
std::string write_screenshot_png(const std::filesystem::path& file, int framebuffer_width, int framebuffer_height,
                                 PixelRect area);

}  // namespace pl::app
