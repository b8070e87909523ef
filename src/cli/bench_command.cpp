// particle-lab bench: particle-steps per second by particle count, scene and method, with a
// hash of the final positions so speed and determinism are checked together.
#include "cli/cli_support.hpp"

#include "io/json_csv.hpp"
#include "physics/stepping/simulation.hpp"
#include "physics/stepping/thread_pool.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <charconv>
#include <chrono>
#include <cstring>
#include <iostream>
#include <memory>

namespace pl::cli {

namespace {

struct BenchOptions {
    bool quick = false, csv = false;
    std::string threads = "1";
};

// FNV-1a (64 bit) over the bytes of the final x, then y, then z coordinates.
std::uint64_t position_hash(const ParticleState& s) {
    std::uint64_t h = 0xcbf29ce484222325ull;
    for (const StateArray<double>* axis : {&s.x, &s.y, &s.z}) {
        for (double d : *axis) {
            unsigned char bytes[sizeof(double)];
            std::memcpy(bytes, &d, sizeof d);
            for (unsigned char b : bytes) {
                h ^= b;
                h *= 0x100000001b3ull;
            }
        }
    }
    return h;
}

struct BenchScene {
    const char* name;
    Scene scene;
};

// Gravity only: a room so large that no particle reaches a wall during the run.
// Gravity + quadratic drag + walls: a 10 m room filled with tennis balls at up to 10 m/s.
std::vector<BenchScene> bench_scenes(std::size_t n) {
    Emitter e;
    e.count = n;
    e.seed = 42;
    e.speed_min = 0.0;
    e.speed_max = 10.0;
    Scene gravity;
    gravity.name = "gravity";
    gravity.room.size = Vec3(1e4);
    gravity.integrator.dt = 0.005;
    gravity.emitter = e;
    gravity.emitter->region_min = Vec3(-5.0);
    gravity.emitter->region_max = Vec3(5.0);
    Scene drag = gravity;
    drag.name = "gravity+quadratic drag+walls";
    drag.room.size = Vec3(10.0);
    drag.drag.model = DragModel::quadratic;
    return {{"gravity", gravity}, {"gravity+drag+walls", drag}};
}

int bench(const BenchOptions& o) {
    std::vector<int> thread_counts;
    for (const std::string& item : CLI::detail::split(o.threads, ',')) {
        int n = -1;
        const auto r = std::from_chars(item.data(), item.data() + item.size(), n);
        if (item.empty() || r.ec != std::errc() || r.ptr != item.data() + item.size() || n < 0) {
            print_error("bench", fmt::format("--threads: expected a comma-separated list of whole numbers >= 0 "
                                             "(0 = all hardware threads), got '{}' in '{}'",
                                             item, o.threads));
            return exit_bad_input;
        }
        thread_counts.push_back(n);
    }
    std::vector<std::size_t> sizes = {1000, 10000, 100000};
    if (!o.quick) sizes.push_back(1000000);
    const double particle_steps = o.quick ? 5e4 : 2e6;
    const std::vector<Method> methods = {Method::explicit_euler, Method::semi_implicit_euler, Method::velocity_verlet,
                                         Method::rk4,            Method::dopri5,              Method::exponential};
    nlohmann::ordered_json rows = nlohmann::ordered_json::array();
    Progress progress("bench");
    const std::size_t total = sizes.size() * 2 * methods.size() * thread_counts.size();
    std::size_t done = 0;
    for (std::size_t n : sizes) {
        for (const BenchScene& b : bench_scenes(n)) {
            const std::vector<ParticleSpec> particles = initial_particles(b.scene);
            for (Method m : methods) {
                for (int threads : thread_counts) {
                    Model model = model_for_variant(b.scene, 0);
                    model.integrator.method = m;
                    Simulation sim(model, particles);
                    sim.set_threads(threads);
                    const auto steps = static_cast<std::uint64_t>(std::max(5.0, particle_steps / static_cast<double>(n)));
                    sim.step();  // warm-up: first touch of the state, thread start-up
                    const auto start = std::chrono::steady_clock::now();
                    sim.step_n(steps);
                    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
                    rows.push_back({{"scene", b.name}, {"method", to_string(m)}, {"particles", n},
                                    {"threads", threads == 0 ? hardware_threads() : static_cast<std::size_t>(threads)},
                                    {"steps", steps}, {"wall_s", seconds},
                                    {"particle_steps_per_s", static_cast<double>(n) * static_cast<double>(steps) / seconds},
                                    {"state_hash_fnv1a", fmt::format("{:016x}", position_hash(sim.state()))}});
                    progress.update(static_cast<double>(++done) / static_cast<double>(total));
                }
            }
        }
    }
    progress.done();
    if (o.csv) {
        write_json_rows_csv(std::cout, rows);
        return exit_ok;
    }
    std::printf("particle-steps per second: dt = 0.005 s, %s particle-steps (at least 5 steps) per row after one\n"
                "untimed warm-up step; the hash covers the final positions and must not depend on the thread count\n\n",
                sig(particle_steps, 2).c_str());
    Table t;
    t.header = {"scene", "method", "particles", "threads", "steps", "seconds", "particle-steps/s", "state hash (FNV-1a)"};
    for (const auto& r : rows)
        t.rows.push_back({r["scene"].get<std::string>(), r["method"].get<std::string>(), r["particles"].dump(),
                          r["threads"].dump(), r["steps"].dump(), sig(r["wall_s"].get<double>(), 3),
                          sig(r["particle_steps_per_s"].get<double>(), 3), r["state_hash_fnv1a"].get<std::string>()});
    t.print();
    return exit_ok;
}

}  // namespace

void add_bench_command(CLI::App& app, int& exit_code) {
    auto o = std::make_shared<BenchOptions>();
    CLI::App* cmd = app.add_subcommand("bench", "particle-steps per second by size and method");
    cmd->footer(
        "Particle-steps per second for 1e3, 1e4, 1e5 and 1e6 particles, gravity only and gravity +\n"
        "quadratic drag + walls, for every method, with a hash of the final positions (the same\n"
        "build must print the same hashes every run).");
    cmd->add_flag("--quick", o->quick, "stop at 1e5 particles and run fewer steps");
    cmd->add_flag("--csv", o->csv, "print CSV (full precision; threads as the count used)");
    cmd->add_option("--threads", o->threads, "comma-separated thread counts to run each row with (0 = all cores)")
        ->capture_default_str();
    add_quiet_flag(cmd);
    cmd->callback([o, &exit_code] { exit_code = bench(*o); });
}

}  // namespace pl::cli
