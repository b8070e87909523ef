#include "bullet_peer.hpp"

#include <algorithm>

#include <btBulletDynamicsCommon.h>

#include <cmath>
#include <map>

namespace pl::bench {

namespace {

btVector3 bt(const Vec3& v) { return {v.x, v.y, v.z}; }
Vec3 pl_vec(const btVector3& v) { return {v.x(), v.y(), v.z()}; }

// The factor that makes the smallest ball 10 cm across in Bullet's units (see the header).
double scale_for(const PeerScene& scene) {
    double smallest = 1.0;
    for (const ParticleSpec& p : scene.particles) smallest = std::min(smallest, p.radius);
    return std::max(1.0, 0.05 / smallest);
}

// Bullet combines two bodies' coefficients by their product (btManifoldResult's
// calculateCombinedRestitution / Friction), so every body carries the square root: ball-ball and
// ball-wall contacts then both see the scene's e and mu, as in particle-lab.
double per_body(double coefficient) { return std::sqrt(coefficient); }

}  // namespace

struct BulletPeer::World {
    btDefaultCollisionConfiguration configuration;
    btCollisionDispatcher dispatcher{&configuration};
    btDbvtBroadphase broadphase;
    btSequentialImpulseConstraintSolver solver;
    btDiscreteDynamicsWorld world{&dispatcher, &broadphase, &solver, &configuration};
    std::map<double, std::unique_ptr<btSphereShape>> spheres;  // one shape per radius
    std::vector<std::unique_ptr<btBoxShape>> wall_shapes;
    std::vector<std::unique_ptr<btDefaultMotionState>> motion_states;
    std::vector<std::unique_ptr<btRigidBody>> walls, balls;
    double dt = 0.0;
    double scale = 1.0;

    ~World() {
        for (auto& b : balls) world.removeRigidBody(b.get());
        for (auto& w : walls) world.removeRigidBody(w.get());
    }

    // Six static boxes, each a slab 1 m thick outside one face of the room.
    void add_walls(const PeerScene& scene) {
        const Vec3 lo = scale * scene.room.min_corner(), hi = scale * scene.room.max_corner(),
                   half = 0.5 * scale * scene.room.size;
        const double thickness = scale;
        for (int axis = 0; axis < 3; ++axis) {
            for (int side = 0; side < 2; ++side) {
                Vec3 extent = half + Vec3(thickness);
                extent[axis] = 0.5 * thickness;
                Vec3 centre = scale * scene.room.center;
                centre[axis] = side == 0 ? lo[axis] - 0.5 * thickness : hi[axis] + 0.5 * thickness;
                wall_shapes.push_back(std::make_unique<btBoxShape>(bt(extent)));
                btTransform at;
                at.setIdentity();
                at.setOrigin(bt(centre));
                motion_states.push_back(std::make_unique<btDefaultMotionState>(at));
                btRigidBody::btRigidBodyConstructionInfo info(0.0, motion_states.back().get(), wall_shapes.back().get());
                info.m_restitution = per_body(scene.restitution);
                info.m_friction = per_body(scene.friction);
                walls.push_back(std::make_unique<btRigidBody>(info));
                world.addRigidBody(walls.back().get());
            }
        }
    }

    void add_ball(const PeerScene& scene, const ParticleSpec& p) {
        auto& shape = spheres[p.radius];
        if (!shape) shape = std::make_unique<btSphereShape>(scale * p.radius);
        btVector3 inertia(0, 0, 0);
        shape->calculateLocalInertia(p.mass, inertia);
        btTransform at;
        at.setIdentity();
        at.setOrigin(bt(scale * p.position));
        motion_states.push_back(std::make_unique<btDefaultMotionState>(at));
        btRigidBody::btRigidBodyConstructionInfo info(p.mass, motion_states.back().get(), shape.get(), inertia);
        info.m_restitution = per_body(scene.restitution);
        info.m_friction = per_body(scene.friction);
        auto body = std::make_unique<btRigidBody>(info);
        body->setLinearVelocity(bt(scale * p.velocity));
        body->setAngularVelocity(bt(p.spin));
        // Continuous collision detection for balls moving more than their radius in a step, so
        // fast pairs do not tunnel here either (particle-lab locates the time of impact).
        body->setCcdMotionThreshold(scale * p.radius);
        body->setCcdSweptSphereRadius(0.9 * scale * p.radius);
        world.addRigidBody(body.get());
        balls.push_back(std::move(body));
    }
};

BulletPeer::BulletPeer(const PeerScene& scene) : world_(std::make_unique<World>()) {
    world_->dt = scene.dt;
    world_->scale = scale_for(scene);
    world_->world.setGravity(bt(world_->scale * scene.gravity));
    world_->add_walls(scene);
    world_->balls.reserve(scene.particles.size());
    for (const ParticleSpec& p : scene.particles) world_->add_ball(scene, p);
    // Bodies inserted one by one leave the dynamic AABB tree unbalanced (Bullet rebalances it a
    // little every step): build it top-down once, as an application loading a level would.
    world_->broadphase.optimize();
}

BulletPeer::~BulletPeer() = default;

// maxSubSteps 0: one step of exactly dt per call (no interpolation, no internal fixed clock).
void BulletPeer::step(int steps) {
    for (int k = 0; k < steps; ++k) world_->world.stepSimulation(world_->dt, 0);
}

std::size_t BulletPeer::size() const { return world_->balls.size(); }

Vec3 BulletPeer::position(std::size_t i) const {
    return pl_vec(world_->balls[i]->getCenterOfMassPosition()) / world_->scale;
}

Vec3 BulletPeer::velocity(std::size_t i) const { return pl_vec(world_->balls[i]->getLinearVelocity()) / world_->scale; }

double BulletPeer::scale() const { return world_->scale; }

std::size_t BulletPeer::contacts() const {
    std::size_t n = 0;
    const int manifolds = world_->dispatcher.getNumManifolds();
    for (int m = 0; m < manifolds; ++m)
        if (world_->dispatcher.getManifoldByIndexInternal(m)->getNumContacts() > 0) ++n;
    return n;
}

}  // namespace pl::bench
