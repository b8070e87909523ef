// Reference (b), the hand-fused limit (hand_fused.cpp), as an object a benchmark can step beside
// the engine: its state and parameters for one workload scene.
#pragma once

#include "workloads.hpp"

#include "physics/stepping/particle_state.hpp"

namespace pl::bench {

// On cache-line boundaries, as the engine's state (ParticleState's StateArray).
struct SoaState {
    StateArray<double> x, y, z, vx, vy, vz;
    StateArray<double> drag_loss;  // with Bookkeeping::drag_ledger only
};

// What the limit keeps besides the state. drag_ledger: the energy each particle has lost to
// drag, integrated as the engine does (mass * h * drag power per step, ParticleState's
// dissipated_drag), which the energy ledger requires of every engine (room-contact issue): its
// limit bounds what any engine keeping that ledger can reach against the plain one.
enum class Bookkeeping { none, drag_ledger };

struct FusedParams {
    double h, k, restitution, mass;
    double gx, gy, gz;
    double lo_x, lo_y, lo_z, hi_x, hi_y, hi_z;  // where the centre touches each wall
};

class FusedLimit {
public:
    explicit FusedLimit(WorkloadScene scene, Bookkeeping bookkeeping = Bookkeeping::none);
    // Back to the scene's initial particles.
    void reload();
    // `steps` steps on `threads` threads, over the engine's particle ranges and blocked as the
    // engine's Simulation::step_n with several steps.
    void step(int threads, int steps);
    const double* positions() const { return s_.x.data(); }

private:
    WorkloadScene scene_;
    Bookkeeping bookkeeping_;
    SoaState s_;
    FusedParams params_{};
};

}  // namespace pl::bench
