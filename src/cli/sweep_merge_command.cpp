// particle-lab sweep-merge: joins the shard files of one sweep into the whole run's file,
// byte for byte what `sweep` writes unsharded; refuses shards of other sweeps, missing or
// repeated shards, and incomplete files.
#include "cli/cli_support.hpp"
#include "cli/sweep_commands.hpp"

#include "io/sweep_table.hpp"

#include <memory>

namespace pl::cli {

namespace {

struct MergeCliOptions {
    std::vector<std::string> files;
    std::string out;
    bool json = false;
};

int sweep_merge(const MergeCliOptions& o) {
    std::vector<SweepFile> shards;
    for (const std::string& file : o.files) {
        std::string error;
        std::optional<SweepFile> f = read_sweep_file(file, error);
        if (!f) {
            print_error("sweep-merge", error);
            return exit_bad_input;
        }
        shards.push_back(std::move(*f));
    }
    std::string error;
    const std::string text = o.json ? merged_sweep_json(shards, o.files, error) : merge_sweep_files(shards, o.files, error);
    if (!error.empty()) {
        print_error("sweep-merge", error);
        return exit_bad_input;
    }
    return write_sweep_output("sweep-merge", o.out, text);
}

}  // namespace

void add_sweep_merge_command(CLI::App& app, int& exit_code) {
    auto o = std::make_shared<MergeCliOptions>();
    CLI::App* cmd = app.add_subcommand("sweep-merge", "join the shard files of one sweep into the whole run's CSV or JSON");
    cmd->footer(
        "The result is byte-identical to the unsharded `particle-lab sweep` output (with --json, to\n"
        "`sweep --json`'s). Every shard of the sweep must be given once (any order), each complete.");
    cmd->add_option("FILES", o->files, "shard CSV files written by sweep --shard I/N")->required();
    cmd->add_flag("--json", o->json, "write the JSON document `sweep --json` writes for the whole run");
    cmd->add_option("--out", o->out, "merged CSV or JSON, written atomically (default: stdout)");
    cmd->callback([o, &exit_code] { exit_code = sweep_merge(*o); });
}

}  // namespace pl::cli
