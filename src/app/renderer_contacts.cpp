#include "app/renderer_contacts.hpp"

#include "physics/collide/collision_pass.hpp"

#include <glm/common.hpp>

#include <algorithm>

namespace pl::app {

namespace {

using collide::SolverContact;

const std::vector<SolverContact>* contacts_of(const Simulation& sim) {
    const collide::CollisionPass* pass = sim.collision_pass();
    return pass ? &pass->contacts() : nullptr;
}

// Visits the contacts of the variants a pane shows.
template <class Visit>
void for_each_contact_list(const Experiment& e, std::optional<std::size_t> only_variant, Visit visit) {
    for (std::size_t v = 0; v < e.variant_count(); ++v) {
        if (only_variant && v != *only_variant) continue;
        if (const std::vector<SolverContact>* list = contacts_of(e.run(v))) visit(e.run(v).state(), *list);
    }
}

// Faint amber for a light load, opaque white for the pane's heaviest (share in [0, 1]): drawn
// through the balls, a pile's many light contacts would otherwise wash the view amber.
glm::vec4 load_color(double share) {
    const auto f = static_cast<float>(std::clamp(share, 0.0, 1.0));
    const glm::vec3 light(1.0f, 0.62f, 0.12f), heavy(1.0f, 1.0f, 1.0f);
    return glm::vec4(glm::mix(light, heavy, f), 0.1f + 0.9f * f);
}

// Loaded, and still where the step left it: a particle launched, kicked or dragged since (paused,
// say) has moved away from the neighbours its listed contacts name.
bool drawable(const ParticleState& s, const SolverContact& c) {
    if (!(c.lambda_n > 0.0)) return false;
    if (c.is_wall()) return true;
    const double reach = s.radius[c.a] + s.radius[c.b];
    return glm::length(s.position(c.b) - s.position(c.a)) <= 1.5 * reach;
}

void append_contact(const ParticleState& s, const SolverContact& c, glm::vec4 color, LineSegments& out) {
    const glm::vec3 a(s.position(c.a));
    const glm::vec3 b = c.is_wall() ? a + glm::vec3(c.n) * static_cast<float>(s.radius[c.a]) : glm::vec3(s.position(c.b));
    add_segment(out, a, b, color);
}

}  // namespace

std::size_t append_contacts(const Experiment& e, std::optional<std::size_t> only_variant, LineSegments& out) {
    double heaviest = 0.0;
    std::size_t loaded = 0;
    for_each_contact_list(e, only_variant, [&](const ParticleState& s, const std::vector<SolverContact>& list) {
        for (const SolverContact& c : list) {
            if (!drawable(s, c)) continue;
            heaviest = std::max(heaviest, c.lambda_n);
            ++loaded;
        }
    });
    if (loaded == 0) return 0;
    const std::size_t stride = (loaded + max_contact_segments - 1) / max_contact_segments;
    std::size_t seen = 0, drawn = 0;
    out.reserve(out.size() + 2 * (loaded / stride + 1));
    for_each_contact_list(e, only_variant, [&](const ParticleState& s, const std::vector<SolverContact>& list) {
        for (const SolverContact& c : list) {
            if (!drawable(s, c) || seen++ % stride != 0) continue;
            append_contact(s, c, load_color(c.lambda_n / heaviest), out);
            ++drawn;
        }
    });
    return drawn;
}

glm::vec3 sleeping_tint(glm::vec3 own) {
    // Grey enough that it reads as asleep next to the palette's blue (variant 0, particle 0) too.
    const glm::vec3 slate(0.46f, 0.50f, 0.57f);
    return glm::mix(slate, own, 0.15f);
}

}  // namespace pl::app
