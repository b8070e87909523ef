#include "app/camera_store.hpp"

#include "app/config_dir.hpp"

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

namespace pl::app {

namespace {

// A saved camera is three short lines; anything bigger is not ours.
constexpr std::uintmax_t max_camera_file_bytes = 4096;

// Camera values past this (in metres or radians) are not a view anyone saved: 3e38 gave a blank
// view. Rooms are at most 1e6 m, so 1e7 keeps every real view.
constexpr float max_camera_value = 1e7f;

bool sane(float v) { return std::isfinite(v) && std::abs(v) <= max_camera_value; }

}  // namespace

std::optional<OrbitCamera> load_camera(const std::filesystem::path& file, const Room& room) {
    if (!readable_settings_file(file, max_camera_file_bytes)) return std::nullopt;
    std::ifstream in(file);
    if (!in) return std::nullopt;
    OrbitCamera c;
    Vec3 center, size;
    bool has_target = false, has_angles = false, has_room = false;
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream fields(line);
        std::string key;
        fields >> key;
        if (key == "target") has_target = static_cast<bool>(fields >> c.target.x >> c.target.y >> c.target.z);
        else if (key == "orbit") has_angles = static_cast<bool>(fields >> c.yaw >> c.pitch >> c.distance);
        else if (key == "room")
            has_room = static_cast<bool>(fields >> center.x >> center.y >> center.z >> size.x >> size.y >> size.z);
    }
    if (!has_target || !has_angles || !has_room) return std::nullopt;
    if (center != room.center || size != room.size) return std::nullopt;
    const bool finite = sane(c.target.x) && sane(c.target.y) && sane(c.target.z) && sane(c.yaw) && sane(c.pitch) &&
                        sane(c.distance);
    if (!finite || !(c.distance > 0.0f)) return std::nullopt;
    return c;
}

void save_camera(const std::filesystem::path& file, const OrbitCamera& c, const Room& room) {
    std::error_code ec;
    const auto status = std::filesystem::status(file, ec);
    if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status)) return;  // a FIFO would block
    std::ofstream out(file);
    if (!out) return;  // remembering the view is a convenience; nothing to report
    out.precision(17);
    out << "target " << c.target.x << ' ' << c.target.y << ' ' << c.target.z << '\n';
    out << "orbit " << c.yaw << ' ' << c.pitch << ' ' << c.distance << '\n';
    out << "room " << room.center.x << ' ' << room.center.y << ' ' << room.center.z << ' ' << room.size.x << ' '
        << room.size.y << ' ' << room.size.z << '\n';
}

}  // namespace pl::app
