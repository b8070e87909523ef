#include "app/screenshot.hpp"

#include <glad/gl.h>
#include <stb_image_write.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace pl::app {

PixelRect to_pixels(float x, float y, float w, float h, float sx, float sy) {
    return {static_cast<int>(std::lround(x * sx)), static_cast<int>(std::lround(y * sy)),
            static_cast<int>(std::lround(w * sx)), static_cast<int>(std::lround(h * sy))};
}

std::string write_screenshot_png(const std::filesystem::path& file, int fb_width, int fb_height, PixelRect area) {
    const int x0 = std::clamp(area.x, 0, fb_width), y0 = std::clamp(area.y, 0, fb_height);
    const int x1 = std::clamp(area.x + area.w, 0, fb_width), y1 = std::clamp(area.y + area.h, 0, fb_height);
    const int width = x1 - x0, height = y1 - y0;
    if (width <= 0 || height <= 0) return "nothing to capture for " + file.string() + ": the area is empty";
    std::vector<unsigned char> pixels(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3);
    glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    // GL's origin is bottom left.
    glReadPixels(x0, fb_height - y1, width, height, GL_RGB, GL_UNSIGNED_BYTE, pixels.data());
    // GL rows run bottom-up; PNG rows top-down.
    stbi_flip_vertically_on_write(1);
    const int ok = stbi_write_png(file.c_str(), width, height, 3, pixels.data(), width * 3);
    stbi_flip_vertically_on_write(0);
    return ok ? std::string{} : "cannot write the screenshot " + file.string();
}

}  // namespace pl::app
