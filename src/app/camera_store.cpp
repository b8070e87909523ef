#include "app/camera_store.hpp"

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

namespace pl::app {

std::optional<OrbitCamera> load_camera(const std::filesystem::path& file, const Room& room) {
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
    const bool finite = std::isfinite(c.target.x) && std::isfinite(c.target.y) && std::isfinite(c.target.z) &&
                        std::isfinite(c.yaw) && std::isfinite(c.pitch) && std::isfinite(c.distance);
    if (!finite || !(c.distance > 0.0f)) return std::nullopt;
    return c;
}

void save_camera(const std::filesystem::path& file, const OrbitCamera& c, const Room& room) {
    std::ofstream out(file);
    if (!out) return;  // remembering the view is a convenience; nothing to report
    out.precision(17);
    out << "target " << c.target.x << ' ' << c.target.y << ' ' << c.target.z << '\n';
    out << "orbit " << c.yaw << ' ' << c.pitch << ' ' << c.distance << '\n';
    out << "room " << room.center.x << ' ' << room.center.y << ' ' << room.center.z << ' ' << room.size.x << ' '
        << room.size.y << ' ' << room.size.z << '\n';
}

}  // namespace pl::app
