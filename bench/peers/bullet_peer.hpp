// The peer for particle-particle collisions: the same spheres in the same room stepped by Bullet
// Physics (Debian's libbullet-dev, double precision: bullet-float64), a btDiscreteDynamicsWorld
// with sphere shapes and six static box walls, the same dt, restitution and friction. Only built
// when pkg-config finds bullet-float64 (PL_HAS_BULLET).
//
// Bullet's tolerances are lengths tuned for bodies of about a metre: its dynamic AABB tree fattens
// every box by 5 cm (DBVT_BP_MARGIN) and keeps contacts up to 2 cm apart. With balls of 5 mm that
// turns every ball within 10 cm of another into a pair (178,000 pairs for 10,000 balls in a 2 m
// box, against 289 once scaled). So the peer steps the scene in units `scale` times larger
// (lengths, velocities and gravity scaled alike, masses and dt kept): the same motion, every
// time the same, with balls of at least 10 cm; positions and velocities are read back in metres.
#pragma once

#include "physics/model/scene.hpp"

#include <cstddef>
#include <memory>
#include <vector>

namespace pl::bench {

// What both engines step: the particles, the room, gravity, dt and the contact constants shared
// by the walls and the pairs (no air: Bullet has no aerodynamic drag).
struct PeerScene {
    Room room;
    Vec3 gravity{0.0, -9.81, 0.0};
    double dt = 0.002;
    double restitution = 0.8;
    double friction = 0.3;
    std::vector<ParticleSpec> particles;
};

class BulletPeer {
public:
    explicit BulletPeer(const PeerScene& scene);
    ~BulletPeer();
    BulletPeer(const BulletPeer&) = delete;
    BulletPeer& operator=(const BulletPeer&) = delete;

    void step(int steps);
    std::size_t size() const;
    Vec3 position(std::size_t i) const;
    Vec3 velocity(std::size_t i) const;
    // Contact manifolds with at least one point after the last step (a collision counter).
    std::size_t contacts() const;
    double scale() const;

private:
    struct World;
    std::unique_ptr<World> world_;
};

}  // namespace pl::bench
