// Reference (a): the object-oriented design most readers start from, written the way the
// practical's framework is (/work/shared/seed/practical-2-newtonian-physics.txt): a PhysicsBody
// base class carrying render data (mesh and shader pointers, colour, position, scale,
// orientation), a Particle subclass per object with a virtual Update, and the forces summed in
// a loop over heap-allocated Force objects with a virtual Apply. Walls: if, clamp, reflect.
// Same workload as the engine (bench/workloads.hpp): same particles, dt, drag, restitution.
#include "registry.hpp"
#include "workloads.hpp"

#include <benchmark/benchmark.h>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <memory>
#include <string>
#include <vector>

namespace pl::bench {

namespace {

namespace oo {

struct Mesh;    // shared GPU data in the framework; never touched by physics
struct Shader;

class PhysicsBody {
public:
    virtual ~PhysicsBody() = default;
    // Immovable bodies (the ground plane) do nothing.
    virtual void Update(double /*dt*/) {}

    const glm::dvec3& Position() const { return m_position; }
    void SetPosition(const glm::dvec3& p) { m_position = p; }

protected:
    Mesh* m_mesh = nullptr;
    Shader* m_shader = nullptr;
    glm::vec4 m_colour{1.0f};
    glm::dvec3 m_position{0.0};
    glm::dvec3 m_scale{1.0};
    glm::dquat m_orientation{1.0, 0.0, 0.0, 0.0};
};

class Particle;

class Force {
public:
    virtual ~Force() = default;
    virtual glm::dvec3 Apply(const Particle& p) const = 0;
};

class Particle : public PhysicsBody {
public:
    struct Room {
        glm::dvec3 min, max;
    };

    Particle(double mass, double radius, double restitution, const Room* room)
        : m_mass(mass), m_radius(radius), m_restitution(restitution), m_room(room) {
        m_scale = glm::dvec3(radius);
    }

    double Mass() const { return m_mass; }
    const glm::dvec3& Velocity() const { return m_velocity; }
    void SetVelocity(const glm::dvec3& v) { m_velocity = v; }
    void AddForce(std::unique_ptr<Force> f) { m_forces.push_back(std::move(f)); }

    void Update(double dt) override {
        glm::dvec3 force(0.0);
        for (const auto& f : m_forces) force += f->Apply(*this);
        const glm::dvec3 acceleration = force / m_mass;
        // Semi-implicit Euler, as in the practical: v += h a, then x += h v.
        m_velocity += dt * acceleration;
        m_position += dt * m_velocity;
        for (int axis = 0; axis < 3; ++axis) {
            const double lo = m_room->min[axis] + m_radius, hi = m_room->max[axis] - m_radius;
            if (m_position[axis] < lo) {
                m_position[axis] = lo;
                m_velocity[axis] = -m_restitution * m_velocity[axis];
            } else if (m_position[axis] > hi) {
                m_position[axis] = hi;
                m_velocity[axis] = -m_restitution * m_velocity[axis];
            }
        }
    }

private:
    double m_mass, m_radius, m_restitution;
    const Room* m_room;
    glm::dvec3 m_velocity{0.0};
    std::vector<std::unique_ptr<Force>> m_forces;
};

class Gravity : public Force {
public:
    explicit Gravity(const glm::dvec3& g) : m_g(g) {}
    glm::dvec3 Apply(const Particle& p) const override { return p.Mass() * m_g; }

private:
    glm::dvec3 m_g;
};

// Newton drag -1/2 rho Cd A |v| v.
class QuadraticDrag : public Force {
public:
    QuadraticDrag(double rho, double cd, double area) : m_coefficient(0.5 * rho * cd * area) {}
    glm::dvec3 Apply(const Particle& p) const override {
        const glm::dvec3& v = p.Velocity();
        return -m_coefficient * glm::length(v) * v;
    }

private:
    double m_coefficient;
};

class PhysicsEngine {
public:
    void Init(const WorkloadScene& scene) {
        const Model& m = scene.model;
        m_room = {m.room.min_corner(), m.room.max_corner()};
        for (const ParticleSpec& spec : scene.particles) {
            auto p = std::make_unique<Particle>(spec.mass, spec.radius, m.contact.restitution, &m_room);
            p->SetPosition(spec.position);
            p->SetVelocity(spec.velocity);
            p->AddForce(std::make_unique<Gravity>(m.world.gravity));
            if (m.drag.model == DragModel::quadratic) {
                const double area = 3.14159265358979323846 * spec.radius * spec.radius;
                p->AddForce(std::make_unique<QuadraticDrag>(m.world.air.density_kg_m3, m.drag.cd, area));
            }
            m_particles.push_back(p.get());
            m_bodies.push_back(std::move(p));
        }
    }
    void Update(double dt) {
        for (const auto& body : m_bodies) body->Update(dt);
    }
    // Back to the initial state for the next window (outside the timing).
    void Reset(const WorkloadScene& scene) {
        for (std::size_t i = 0; i < m_particles.size(); ++i) {
            m_particles[i]->SetPosition(scene.particles[i].position);
            m_particles[i]->SetVelocity(scene.particles[i].velocity);
        }
    }
    const glm::dvec3& FirstPosition() const { return m_bodies.front()->Position(); }

private:
    Particle::Room m_room{};
    std::vector<std::unique_ptr<PhysicsBody>> m_bodies;
    std::vector<Particle*> m_particles;
};

}  // namespace oo

void run_baseline(benchmark::State& state, std::size_t n) {
    const WorkloadScene scene = make_workload(Workload::drag_walls, n);
    oo::PhysicsEngine engine;
    engine.Init(scene);
    const double dt = scene.model.integrator.dt;
    int steps = 0;
    for (auto _ : state) {
        if (steps == steps_per_window) {
            state.PauseTiming();
            engine.Reset(scene);
            steps = 0;
            state.ResumeTiming();
        }
        engine.Update(dt);
        ++steps;
    }
    benchmark::DoNotOptimize(engine.FirstPosition());
    state.counters[rate_counter] =
        benchmark::Counter(static_cast<double>(state.iterations()) * static_cast<double>(n), benchmark::Counter::kIsRate);
}

}  // namespace

void register_baseline_benchmarks() {
    for (std::size_t n : sizes)
        benchmark::RegisterBenchmark(("baseline_oo/drag_walls/n:" + size_label(n)).c_str(),
                                     [n](benchmark::State& state) { run_baseline(state, n); })
            ->UseRealTime()
            ->Unit(benchmark::kMicrosecond);
}

}  // namespace pl::bench
