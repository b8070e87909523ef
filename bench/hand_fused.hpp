// Reference (b), the hand-fused limit (hand_fused.cpp), as an object a benchmark can step beside
// the engine: its state and parameters for one workload scene.
#pragma once

#include "workloads.hpp"

#include "physics/particle_state.hpp"

namespace pl::bench {

// On cache-line boundaries, as the engine's state (ParticleState's StateArray).
struct SoaState {
    StateArray<double> x, y, z, vx, vy, vz;
};

struct FusedParams {
    double h, k, restitution;
    double gx, gy, gz;
    double lo_x, lo_y, lo_z, hi_x, hi_y, hi_z;  // where the centre touches each wall
};

class FusedLimit {
public:
    explicit FusedLimit(WorkloadScene scene);
    // Back to the scene's initial particles.
    void reload();
    // `steps` steps on `threads` threads, over the engine's particle ranges and blocked as the
    // engine's Simulation::step_n with several steps.
    void step(int threads, int steps);
    const double* positions() const { return s_.x.data(); }

private:
    WorkloadScene scene_;
    SoaState s_;
    FusedParams params_{};
};

}  // namespace pl::bench
