#include "app/data_dir.hpp"

#include <cstdlib>
#include <sstream>

namespace pl::app {

namespace {

namespace fs = std::filesystem;

std::string env_or(const char* name, const std::string& fallback) {
    const char* value = std::getenv(name);
    return value && *value ? value : fallback;
}

}  // namespace

std::vector<fs::path> data_dir_candidates() {
    std::vector<fs::path> dirs;
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        dirs.push_back(exe.parent_path().parent_path() / "share" / "particle-lab");
        dirs.push_back(exe.parent_path() / "share" / "particle-lab");
    }
    const std::string home = env_or("HOME", "");
    const std::string data_home = env_or("XDG_DATA_HOME", home.empty() ? "" : home + "/.local/share");
    if (!data_home.empty()) dirs.push_back(fs::path(data_home) / "particle-lab");
    std::istringstream search(env_or("XDG_DATA_DIRS", "/usr/local/share:/usr/share"));
    for (std::string dir; std::getline(search, dir, ':');)
        if (!dir.empty()) dirs.push_back(fs::path(dir) / "particle-lab");
    return dirs;
}

fs::path data_dir() {
    std::error_code ec;
    for (const fs::path& dir : data_dir_candidates())
        if (fs::is_directory(dir / "presets", ec) && fs::is_directory(dir / "shaders", ec)) return dir;
    return {};
}

fs::path data_path(const std::string& sub) {
    const fs::path dir = data_dir();
    return dir.empty() ? fs::path(sub) : dir / sub;
}

}  // namespace pl::app
