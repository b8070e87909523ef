// particle-lab validate: load a preset and report every problem, or a one-line summary.
#include "cli/cli_support.hpp"

#include <memory>

namespace pl::cli {

namespace {

int validate(const std::string& path) {
    const std::optional<Scene> scene = load_scene("validate", path);
    if (!scene) return exit_bad_input;
    const std::size_t particles = scene->particles.size() + (scene->emitter ? scene->emitter->count : 0);
    const std::size_t variants = scene->variants.size();
    std::printf("ok: %zu particle%s, %zu variant%s\n", particles, particles == 1 ? "" : "s", variants,
                variants == 1 ? "" : "s");
    return exit_ok;
}

}  // namespace

void add_validate_command(CLI::App& app, int& exit_code) {
    auto path = std::make_shared<std::string>();
    CLI::App* cmd = app.add_subcommand("validate", "check a preset: exit 0, or 2 printing every error");
    cmd->footer(
        "Check a preset: exit 0 printing 'ok: N particles, M variants', or exit 2 printing every\n"
        "error with its JSON path and the rule broken.");
    cmd->add_option("PRESET", *path, "preset JSON file")->required();
    cmd->callback([path, &exit_code] { exit_code = validate(*path); });
}

}  // namespace pl::cli
