#include "app/screenshot.hpp"

#include <glad/gl.h>
#include <stb_image_write.h>

#include <vector>

namespace pl::app {

std::string write_screenshot_png(const std::filesystem::path& file, int width, int height) {
    if (width <= 0 || height <= 0) return "the window has no pixels to capture";
    std::vector<unsigned char> pixels(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3);
    glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, pixels.data());
    // GL rows run bottom-up; PNG rows top-down.
    stbi_flip_vertically_on_write(1);
    const int ok = stbi_write_png(file.c_str(), width, height, 3, pixels.data(), width * 3);
    stbi_flip_vertically_on_write(0);
    return ok ? std::string{} : "cannot write the screenshot " + file.string();
}

}  // namespace pl::app
