#include "physics/studies/resource_estimate.hpp"

#include "physics/stepping/particle_state.hpp"
#include "physics/stepping/warnings.hpp"

#include <fmt/format.h>

#include <cinttypes>
#include <cstdio>

namespace pl {

namespace {

// Fastest rates measured (README, Performance; bench/RESULTS.md): about 1e9 particle-steps per
// second on two threads for large scenes, and about 2e-7 s of overhead per step of a one-ball
// scene (1e7 steps in 2.1 s of CPU). Half that overhead is used so the estimate stays a lower
// bound.
constexpr double fastest_particle_steps_per_s = 1e9;
// With collisions on: the dilute gas of 1e4 on two threads, 13 ns a particle-step (7.5e7 a
// second), the fastest collision scene measured; rounded up to stay a lower bound on the time.
constexpr double fastest_colliding_particle_steps_per_s = 1e8;
constexpr double least_seconds_per_step = 1e-7;

// The collision pass's peak, per particle: poured balls settling into a pile (the densest
// contacts; the dilute gas needs less) took 1.9 KB a ball at 5e4 balls and 3.0 KB at 2e5 more
// than the same run with collisions off (peak resident size). Rounded up: a refusal must not
// let through a scene that then fails half-way through its allocations.
constexpr std::uint64_t collision_pass_bytes = 4096;

}  // namespace

WorkEstimate work_of(const Scene& scene, double steps) {
    WorkEstimate w{scene.particles.size() + (scene.emitter ? scene.emitter->count : 0), variant_count(scene), steps};
    for (std::size_t v = 0; v < w.variants; ++v) w.collision_variants += model_for_variant(scene, v).collisions.enabled;
    return w;
}

std::string duration_text(double s) {
    if (s < 120.0) return fmt::format("{:.0f} s", s);
    if (s < 7200.0) return fmt::format("{:.0f} minutes", s / 60.0);
    if (s < 2.0 * 86400.0) return fmt::format("{:.1f} hours", s / 3600.0);
    if (s < 365.0 * 86400.0) return fmt::format("{:.0f} days", s / 86400.0);
    return fmt::format("{:.3g} years", s / (365.25 * 86400.0));
}

std::string counts_text(const WorkEstimate& w) {
    return fmt::format("{} particle{} x {} variant{}", w.particles, w.particles == 1 ? "" : "s", w.variants,
                       w.variants == 1 ? "" : "s");
}

std::string bytes_text(double b) { return fmt::format("{:.3g} GB", b / 1e9); }

std::uint64_t bytes_per_particle_per_variant() {
    // ParticleState is a structure of arrays, none with elements wider than a double; its size
    // over one array's counts the arrays. Then the warning bits.
    static_assert(sizeof(ParticleState) % sizeof(StateArray<double>) == 0, "ParticleState holds only StateArrays");
    return sizeof(ParticleState) / sizeof(StateArray<double>) * sizeof(double) + sizeof(WarningBits);
}

std::uint64_t initial_bytes_per_particle() { return sizeof(ParticleSpec); }

std::uint64_t collision_bytes_per_particle() { return collision_pass_bytes; }

double estimated_bytes(const WorkEstimate& w) {
    return static_cast<double>(w.particles) *
           (static_cast<double>(w.variants) * static_cast<double>(bytes_per_particle_per_variant()) +
            static_cast<double>(w.collision_variants) * static_cast<double>(collision_bytes_per_particle()) +
            static_cast<double>(initial_bytes_per_particle()));
}

double estimated_seconds(const WorkEstimate& w) {
    const double variant_steps = w.steps * static_cast<double>(w.variants);
    const double colliding_steps = w.steps * static_cast<double>(w.collision_variants);
    const auto n = static_cast<double>(w.particles);
    return (variant_steps - colliding_steps) * n / fastest_particle_steps_per_s +
           colliding_steps * n / fastest_colliding_particle_steps_per_s + variant_steps * least_seconds_per_step;
}

std::uint64_t available_memory_bytes() {
    std::FILE* f = std::fopen("/proc/meminfo", "r");
    if (!f) return 0;
    char line[256];
    std::uint64_t kb = 0;
    while (std::fgets(line, sizeof line, f))
        if (std::sscanf(line, "MemAvailable: %" SCNu64 " kB", &kb) == 1) break;
    std::fclose(f);
    return kb * 1024;
}

std::string memory_refusal(const WorkEstimate& w) {
    const double bytes = estimated_bytes(w);
    const std::uint64_t available = available_memory_bytes();
    if (available == 0 || bytes <= static_cast<double>(available)) return "";
    const std::string collisions =
        w.collision_variants == 0
            ? std::string{}
            : fmt::format(", and {} bytes more per particle in the {} variant{} with collisions",
                          collision_bytes_per_particle(), w.collision_variants, w.collision_variants == 1 ? "" : "s");
    return fmt::format("needs about {} of memory ({} x {} bytes{}), but the machine has {} available; use fewer "
                       "particles or variants{}",
                       bytes_text(bytes), counts_text(w), bytes_per_particle_per_variant(), collisions,
                       bytes_text(static_cast<double>(available)), w.collision_variants == 0 ? "" : ", or turn collisions off");
}

}  // namespace pl
