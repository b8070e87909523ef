#include "physics/collide/pair_crossings.hpp"

#include <glm/geometric.hpp>

#include <algorithm>

namespace pl::collide {

void find_crossings(const std::vector<Pair>& pairs, const std::vector<Vec3>& start, const ParticleState& s,
                    const std::vector<std::uint8_t>& asleep, double touching_share, std::vector<PairCrossing>& out) {
    for (const Pair& p : pairs) {
        if (asleep[p.a] && asleep[p.b]) continue;
        const Vec3 d0 = start[p.b] - start[p.a], d1 = s.position(p.b) - s.position(p.a);
        if (!(glm::dot(d0, d1) < 0.0)) continue;  // the cheap test first: almost every pair stays on its side
        const double contact = s.radius[p.a] + s.radius[p.b];
        if (glm::length(d0) < (1.0 - touching_share) * contact) continue;  // deep from the start (an emitter's)
        // The point of the segment d0 -> d1 nearest the origin (Ericson 2005, sec. 5.1.2).
        const Vec3 e = d1 - d0;
        const double ee = glm::dot(e, e);
        const double t = ee > 0.0 ? std::clamp(-glm::dot(d0, e) / ee, 0.0, 1.0) : 0.0;
        if (glm::length(d0 + t * e) < contact) out.push_back({p.a, p.b, std::sqrt(ee) / contact});
    }
}

}  // namespace pl::collide
