// The stability study's collision slice: two balls thrown at each other across the room, on one
// line along x at the room's centre and a little upward (0.3 of the speed), with the walls'
// friction between them. The cell runs as long as a single particle's would (StabilityRunLimits)
// and is classified at every step's end, first outcome first:
//   nan        a ball's state became non-finite (the engine froze it);
//   tunnelled  a centre left the room, or one ball passed through the other: their order along x
//              flipped in one step that began and ended with them level (neither above nor
//              beside the other by a contact distance), where no path could go around; the
//              detail says whether the engine warned (collision_overlap or collision_crossing);
//   escaped    a sphere went into a wall;
//   overlap    the pair was left deeper in each other than collision_overlap_limit of their
//              contact distance (the detail says whether the engine warned);
//   energy_growth  KE + spin + PE of the pair above E0 by stability_energy_tolerance (no source).
#include "physics/studies/stability_study.hpp"

#include "physics/stepping/contact.hpp"
#include "physics/stepping/energy.hpp"
#include "physics/stepping/simulation.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace pl {

namespace {

Model pair_model(const StabilityBase& base, const StabilityCase& c) {
    Model m = stability_model(base, c, "stability pair");
    m.collisions.enabled = true;
    m.collisions.restitution = c.restitution;
    m.collisions.friction = base.contact.friction;
    return m;
}

std::vector<ParticleSpec> pair_particles(const StabilityBase& base, const StabilityCase& c) {
    const double min_size = std::min({base.room.size.x, base.room.size.y, base.room.size.z});
    const double r0 = c.radius_fraction * min_size;
    // Ball 1 no larger than a fifth of the room, so the pair starts apart and inside it.
    const double r1 = std::min(r0 * c.pair_radius_ratio, 0.2 * min_size);
    const double half_gap = 0.15 * base.room.size.x + 0.5 * (r0 + r1);
    ParticleSpec a, b;
    a.position = base.room.center - Vec3(half_gap, 0.0, 0.0);
    b.position = base.room.center + Vec3(half_gap, 0.0, 0.0);
    a.velocity = Vec3(c.speed, 0.3 * c.speed, 0.0);
    b.velocity = Vec3(-c.speed, 0.3 * c.speed, 0.0);
    a.mass = base.mass;
    b.mass = base.mass * c.pair_mass_ratio;
    a.radius = r0;
    b.radius = r1;
    return {a, b};
}

}  // namespace

StabilityCell classify_pair(const StabilityBase& base, const StabilityCase& c, const StabilityRunLimits& limits) {
    StabilityCell cell;
    cell.c = c;
    const Model m = pair_model(base, c);
    Simulation sim(m, pair_particles(base, c));
    sim.set_threads(1);  // cells already run in parallel
    const double e0 = total_energy(sim.state(), base.gravity, base.room).total_mechanical();
    const double g = glm::length(base.gravity);
    const double energy_scale = std::max(e0, (base.mass * (1.0 + c.pair_mass_ratio)) * g * 1e-3);
    cell.max_energy_ratio = 1.0;
    auto finish = [&](StabilityOutcome o, std::string detail) { return finish_cell(cell, sim, o, std::move(detail)); };
    auto warned = [&] {
        return std::any_of(sim.warnings().begin(), sim.warnings().end(),
                           [](const Warning& w) {
                               return w.kind == WarningKind::collision_overlap || w.kind == WarningKind::collision_crossing;
                           });
    };
    const ParticleState& s = sim.state();
    const double contact = s.radius[0] + s.radius[1];
    // Level: neither above nor beside the other by a contact distance (ball 1 starts at +x).
    const auto level = [contact](const Vec3& gap) { return std::abs(gap.y) < contact && std::abs(gap.z) < contact; };
    Vec3 last_gap = s.position(1) - s.position(0);
    const std::uint64_t steps = stability_steps(c, limits);
    for (std::uint64_t k = 0; k < steps; ++k) {
        sim.step();
        for (std::uint32_t i = 0; i < 2; ++i) {
            if (s.frozen[i])
                return finish(StabilityOutcome::nan, fmt::format("t = {:.6g} s: ball {} became non-finite", sim.time(), i));
            if (std::optional<WallOutcome> w = wall_outcome(base.room, s.position(i), s.radius[i], sim.time(), fmt::format("ball {}", i)))
                return finish(w->outcome, std::move(w->detail));
        }
        const Vec3 gap = s.position(1) - s.position(0);
        if (level(last_gap) && level(gap) && gap.x * last_gap.x < 0.0) {
            cell.collision_warned = warned();
            return finish(StabilityOutcome::tunnelled, fmt::format("t = {:.6g} s: one ball passed through the other ({})", sim.time(),
                                                                   cell.collision_warned ? "warned" : "not warned"));
        }
        last_gap = gap;
        const double depth = 1.0 - glm::length(gap) / contact;
        cell.max_overlap = std::max(cell.max_overlap, depth);
        if (depth > collision_overlap_limit) {
            cell.collision_warned = warned();
            return finish(StabilityOutcome::overlap,
                          fmt::format("t = {:.6g} s: {:.3g} of the contact distance deep ({})", sim.time(), depth,
                                      cell.collision_warned ? "warned" : "not warned"));
        }
        const double energy = total_energy(s, base.gravity, base.room).total_mechanical();
        if (std::optional<std::string> grown = energy_grown(cell, energy, e0, energy_scale, sim.time()))
            return finish(StabilityOutcome::energy_growth, std::move(*grown));
    }
    cell.collision_warned = warned();
    return finish(StabilityOutcome::stable, "");
}

}  // namespace pl
