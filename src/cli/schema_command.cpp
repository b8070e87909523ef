// particle-lab schema: print the preset format as a JSON Schema (draft 2020-12), generated from
// the same rows the loader reads by.
#include "cli/cli_support.hpp"

#include "io/preset_json_schema.hpp"
#include "io/preset_reference.hpp"

#include <memory>

namespace pl::cli {

void add_schema_command(CLI::App& app, int& exit_code) {
    CLI::App* cmd = app.add_subcommand("schema", "print the preset JSON Schema (draft 2020-12)");
    cmd->footer(
        "Print the preset format as a JSON Schema (draft 2020-12), generated from the preset rows.\n"
        "A schema cannot state every rule (a particle must fit the room, labels be unique, keys\n"
        "appear once): 'particle-lab validate' is the full check. --fuzz-dict prints the tokens of\n"
        "fuzz/preset.dict instead.");
    auto fuzz_dict = std::make_shared<bool>(false);
    cmd->add_flag("--fuzz-dict", *fuzz_dict,
                  "print the libFuzzer dictionary tokens of the format instead (every key and enumeration value)");
    cmd->callback([fuzz_dict, &exit_code] {
        std::fputs((*fuzz_dict ? preset_fuzz_dictionary() : preset_json_schema()).c_str(), stdout);
        exit_code = exit_ok;
    });
}

}  // namespace pl::cli
