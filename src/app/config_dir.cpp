#include "app/config_dir.hpp"

#include <cstdlib>

namespace pl::app {

std::optional<std::filesystem::path> user_config_dir() {
    std::filesystem::path base;
    if (const char* xdg = std::getenv("XDG_CONFIG_HOME"); xdg && *xdg) base = xdg;
    else if (const char* home = std::getenv("HOME"); home && *home) base = std::filesystem::path(home) / ".config";
    else return std::nullopt;
    const std::filesystem::path dir = base / "particle-lab";
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec || !std::filesystem::is_directory(dir)) return std::nullopt;
    return dir;
}

bool readable_settings_file(const std::filesystem::path& file, std::uintmax_t max_bytes) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec) || ec) return false;  // follows symlinks
    const std::uintmax_t size = std::filesystem::file_size(file, ec);
    return !ec && size <= max_bytes;
}

}  // namespace pl::app
