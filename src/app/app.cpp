#include "app/app.hpp"

#include "app/data_dir.hpp"
#include "app/frame_loop.hpp"
#include "app/gui_options.hpp"
#include "io/preset_io.hpp"
#include "ui/lab_session.hpp"

#include <cstdio>

#include <exception>

namespace pl::app {

int run_gui(int argc, char** argv) {
    const ParsedGuiOptions parsed = parse_gui_options(argc, argv);
    if (!parsed.options) return parsed.exit_code;
    const GuiOptions& options = *parsed.options;

    // A preset that does not load is bad input: report every error and open no window.
    const LoadResult preset = load_preset(options.preset);
    if (!preset.ok()) {
        std::fprintf(stderr, "particle-lab: cannot load %s:\n%s\n", options.preset.string().c_str(),
                     preset.error_text().c_str());
        return 2;
    }
    ui::LabSession session;
    session.preset_dir = data_path("presets");
    if (const std::string refused = session.open_preset(*preset.scene, options.preset); !refused.empty()) {
        std::fprintf(stderr, "particle-lab: cannot open %s: %s\n", options.preset.string().c_str(), refused.c_str());
        return 2;
    }
    if (options.time_scale) session.time_scale = *options.time_scale;
    session.status_message = "Loaded " + options.preset.filename().string();
    try {
        return run_frame_loop(session, options);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "particle-lab: %s\n", e.what());
        return 1;
    }
}

}  // namespace pl::app
