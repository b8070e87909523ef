// particle-lab validate: load a preset and report every problem, or a one-line summary;
// `--format` prints the format reference generated from the preset rows instead.
#include "cli/cli_support.hpp"

#include "io/preset_reference.hpp"

#include <memory>

namespace pl::cli {

namespace {

struct ValidateOptions {
    std::string path;
    std::vector<std::string> sets;  // --set KEY=VALUE: validate the preset as overridden
    bool format = false;
};

int validate(const ValidateOptions& o) {
    if (o.format) {
        std::fputs(preset_format_reference().c_str(), stdout);
        return exit_ok;
    }
    if (o.path.empty()) {
        std::fprintf(stderr, "particle-lab validate: PRESET is required (or --format)\n");
        return exit_bad_input;
    }
    const std::optional<Scene> scene = load_scene("validate", o.path, o.sets);
    if (!scene) return exit_bad_input;
    const std::size_t particles = scene->particles.size() + (scene->emitter ? scene->emitter->count : 0);
    const std::size_t variants = scene->variants.size();
    std::printf("ok: %zu particle%s, %zu variant%s\n", particles, particles == 1 ? "" : "s", variants,
                variants == 1 ? "" : "s");
    return exit_ok;
}

}  // namespace

void add_validate_command(CLI::App& app, int& exit_code) {
    auto o = std::make_shared<ValidateOptions>();
    CLI::App* cmd = app.add_subcommand("validate", "check a preset: exit 0, or 2 printing every error");
    cmd->footer(
        "Check a preset: exit 0 printing 'ok: N particles, M variants', or exit 2 printing every\n"
        "error with its JSON path and the rule broken. --format prints the preset format reference.");
    cmd->add_option("PRESET", o->path, "preset JSON file (-: standard input)");
    add_set_option(cmd, o->sets);
    cmd->add_flag("--format", o->format, "print the preset format reference (every key, unit, bound, default)");
    cmd->callback([o, &exit_code] { exit_code = validate(*o); });
}

}  // namespace pl::cli
