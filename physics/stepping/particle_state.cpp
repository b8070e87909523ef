#include "physics/stepping/particle_state.hpp"

namespace pl {

const char* wall_name(int wall) {
    static const char* names[] = {"x_min", "x_max", "y_min", "y_max", "z_min", "z_max"};
    return wall >= 0 && wall < wall_count ? names[wall] : "none";
}

void ParticleState::resize(std::size_t n) {
    for (auto* v : {&x, &y, &z, &vx, &vy, &vz, &mass, &radius, &drag_k, &drag_re_scale, &dissipated_bounce,
                    &dissipated_friction, &dissipated_drag, &wind_work, &initial_energy, &wx, &wy, &wz, &inertia, &dissipated_rolling,
                    &inertial_mass})
        v->assign(n, 0.0);
    resting.assign(n, 0);
    frozen.assign(n, 0);
}

}  // namespace pl
