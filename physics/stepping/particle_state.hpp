// Evolving state of all particles of one simulation, structure-of-arrays (hot loops stream it).
#pragma once

#include "physics/model/scene.hpp"

#include <cstddef>
#include <cstdint>
#include <new>
#include <vector>

namespace pl {

// The six walls, in this order; the bit (1 << wall) marks a particle resting on that wall.
enum Wall : std::uint8_t { x_min = 0, x_max = 1, y_min = 2, y_max = 3, z_min = 4, z_max = 5 };
constexpr int wall_count = 6;
const char* wall_name(int wall);  // "x_min" ... "z_max"

// Allocates on 64-byte cache-line boundaries. malloc's 16-byte alignment made every 64-byte
// vector load of the stepping loops straddle two cache lines, and let the line at the border of
// two threads' particle ranges be written by both.
template <class T>
struct CacheLineAllocator {
    using value_type = T;
    static constexpr std::align_val_t alignment{64};
    CacheLineAllocator() = default;
    template <class U>
    CacheLineAllocator(const CacheLineAllocator<U>&) {}
    T* allocate(std::size_t n) { return static_cast<T*>(::operator new(n * sizeof(T), alignment)); }
    void deallocate(T* p, std::size_t) { ::operator delete(p, alignment); }
    template <class U>
    bool operator==(const CacheLineAllocator<U>&) const { return true; }
};
template <class T>
using StateArray = std::vector<T, CacheLineAllocator<T>>;

struct ParticleState {
    StateArray<double> x, y, z;
    StateArray<double> vx, vy, vz;
    StateArray<double> mass, radius;
    StateArray<double> drag_k, drag_re_scale;  // see DragCoefficients
    StateArray<std::uint8_t> resting;          // bit mask of walls it rests on
    StateArray<std::uint8_t> frozen;           // 1: state became non-finite, no longer stepped
    StateArray<double> wx, wy, wz;             // angular velocity, rad/s (stepped only where spin_matters)
    StateArray<double> inertia;                // k in I = k m R^2 (2/5 solid, 2/3 hollow)

    // Energy ledger, J, accumulated since the start.
    StateArray<double> dissipated_bounce, dissipated_friction, dissipated_drag, wind_work;
    StateArray<double> dissipated_rolling;  // by rolling resistance (contact.spin)
    StateArray<double> initial_energy;  // KE + spin KE + PE at t = 0
    // The inertial mass at the particle's position: m, or m + 1/2 rho V with added mass (rho the
    // air's at its height, physics/model/air_model.hpp); the kinetic energy is 1/2 this v^2.
    StateArray<double> inertial_mass;
    // Energy the particle-particle impulses gave each particle (< 0 in sum: what they dissipate).
    // Allocated only where collisions are enabled (empty otherwise; resize leaves it alone).
    StateArray<double> collision_work;

    std::size_t size() const { return x.size(); }
    Vec3 position(std::size_t i) const { return {x[i], y[i], z[i]}; }
    Vec3 velocity(std::size_t i) const { return {vx[i], vy[i], vz[i]}; }
    void set_position(std::size_t i, const Vec3& p) { x[i] = p.x; y[i] = p.y; z[i] = p.z; }
    void set_velocity(std::size_t i, const Vec3& v) { vx[i] = v.x; vy[i] = v.y; vz[i] = v.z; }
    Vec3 spin(std::size_t i) const { return {wx[i], wy[i], wz[i]}; }
    // I = k m R^2 (the bare mass: added mass does not turn with a sphere), kg m^2.
    double moment(std::size_t i) const { return inertia[i] * mass[i] * radius[i] * radius[i]; }
    void set_spin(std::size_t i, const Vec3& w) { wx[i] = w.x; wy[i] = w.y; wz[i] = w.z; }
    void resize(std::size_t n);
};

}  // namespace pl
