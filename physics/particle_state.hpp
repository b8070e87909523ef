// Evolving state of all particles of one simulation, structure-of-arrays (hot loops stream it).
#pragma once

#include "scene.hpp"

#include <cstdint>
#include <vector>

namespace pl {

// The six walls, in this order; the bit (1 << wall) marks a particle resting on that wall.
enum Wall : std::uint8_t { x_min = 0, x_max = 1, y_min = 2, y_max = 3, z_min = 4, z_max = 5 };
constexpr int wall_count = 6;
const char* wall_name(int wall);  // "x_min" ... "z_max"

struct ParticleState {
    std::vector<double> x, y, z;
    std::vector<double> vx, vy, vz;
    std::vector<double> mass, radius;
    std::vector<double> drag_k, drag_re_scale;  // see DragCoefficients
    std::vector<std::uint8_t> resting;          // bit mask of walls it rests on
    std::vector<std::uint8_t> frozen;           // 1: state became non-finite, no longer stepped

    // Energy ledger, J, accumulated since the start.
    std::vector<double> dissipated_bounce, dissipated_friction, dissipated_drag, wind_work;
    std::vector<double> initial_energy;  // KE + PE at t = 0

    std::size_t size() const { return x.size(); }
    Vec3 position(std::size_t i) const { return {x[i], y[i], z[i]}; }
    Vec3 velocity(std::size_t i) const { return {vx[i], vy[i], vz[i]}; }
    void set_position(std::size_t i, const Vec3& p) { x[i] = p.x; y[i] = p.y; z[i] = p.z; }
    void set_velocity(std::size_t i, const Vec3& v) { vx[i] = v.x; vy[i] = v.y; vz[i] = v.z; }
    void resize(std::size_t n);
};

}  // namespace pl
