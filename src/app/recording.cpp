#include "app/recording.hpp"

#include "app/data_dir.hpp"

#include <glad/gl.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <ctime>

namespace pl::app {

namespace fs = std::filesystem;

namespace {

// Whether `file` would land inside `folder` (both resolved through symlinks: the build tree's
// data folder links to the source presets/).
bool inside(const fs::path& file, const fs::path& folder) {
    std::error_code ec;
    const fs::path f = fs::weakly_canonical(fs::absolute(file, ec), ec);
    const fs::path d = fs::weakly_canonical(folder, ec);
    if (ec || d.empty()) return false;
    const auto mismatch = std::mismatch(d.begin(), d.end(), f.begin(), f.end());
    return mismatch.first == d.end();
}

}  // namespace

const std::vector<RecordAreaName>& record_areas() {
    static const std::vector<RecordAreaName> areas = {
        {RecordArea::window, "window", "Whole window"},
        {RecordArea::view, "view", "3D view"},
        {RecordArea::plots, "plots", "Plots"},
        {RecordArea::view_and_plots, "view+plots", "3D view and plots"},
    };
    return areas;
}

std::optional<RecordArea> parse_record_area(const std::string& name) {
    for (const RecordAreaName& a : record_areas())
        if (name == a.name) return a.area;
    return std::nullopt;
}

Rect record_rect(RecordArea area, const ShellLayout& l, float display_w, float display_h) {
    switch (area) {
        case RecordArea::view: return l.view;
        case RecordArea::plots: return l.plots;
        case RecordArea::view_and_plots: {
            // The toolbar's row and the view below it, with the plots column to their right.
            const float top = std::min(l.toolbar.y, l.plots.y);
            const float bottom = std::max(l.view.bottom(), l.plots.bottom());
            return {l.view.x, top, l.plots.right() - l.view.x, bottom - top};
        }
        case RecordArea::window: break;
    }
    return {0.0f, 0.0f, display_w, display_h};
}

std::string check_record_file(const fs::path& file, const std::string& what) {
    if (std::string bad = check_recording_target(file, what); !bad.empty()) return bad;
    for (const char* shipped : {"presets", "shaders"})
        if (inside(file, data_path(shipped)))
            return what + ": '" + file.string() + "' is in the shipped " + shipped + " folder; record elsewhere";
    return {};
}

std::string Recorder::start(const RecordSettings& settings, PixelRect area) {
    if (std::string bad = check_record_file(settings.file, "recording"); !bad.empty()) return bad;
    if (settings.fps < min_record_fps || settings.fps > max_record_fps)
        return "recording: the frame rate must be " + std::to_string(min_record_fps) + " to " +
               std::to_string(max_record_fps) + " fps";
    // H.264 and VP9 in 4:2:0 need even sizes: drop an odd last row or column.
    area.w -= area.w % 2;
    area.h -= area.h % 2;
    if (area.w < 2 || area.h < 2) return "recording: the area to record is empty";
    if (std::string error = pipe_.open(settings.file, area.w, area.h, settings.fps); !error.empty()) return error;
    settings_ = settings;
    area_ = area;
    frames_ = 0;
    pixels_.assign(static_cast<std::size_t>(area.w) * static_cast<std::size_t>(area.h) * 3, 0);
    return {};
}

std::optional<double> Recorder::frame_dt() const {
    if (!active()) return std::nullopt;
    return 1.0 / settings_.fps;
}

std::string Recorder::capture(int fb_w, int fb_h) {
    if (!active()) return {};
    if (area_.x + area_.w > fb_w || area_.y + area_.h > fb_h) {
        pipe_.cancel();
        return "recording stopped: the window became smaller than the recorded area";
    }
    glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    // GL's origin is bottom left; the rows stay bottom-up and ffmpeg flips them (vflip).
    glReadPixels(area_.x, fb_h - area_.y - area_.h, area_.w, area_.h, GL_RGB, GL_UNSIGNED_BYTE, pixels_.data());
    if (std::string error = pipe_.write_frame(pixels_.data()); !error.empty()) return error;
    ++frames_;
    return {};
}

bool Recorder::done() const {
    return active() && settings_.seconds && frames_ >= std::lround(*settings_.seconds * settings_.fps);
}

std::string Recorder::stop() { return pipe_.finish(); }

fs::path default_record_file(const std::string& preset_name, const char* extension) {
    fs::path dir = fs::current_path();
    std::error_code ec;
    if (const char* videos = std::getenv("XDG_VIDEOS_DIR"); videos && *videos) {
        dir = videos;
    } else if (const char* home = std::getenv("HOME"); home && *home && fs::is_directory(fs::path(home) / "Videos", ec)) {
        dir = fs::path(home) / "Videos";
    }
    char stamp[32];
    const std::time_t now = std::time(nullptr);
    std::tm local{};
    localtime_r(&now, &local);
    std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", &local);
    const std::string stem = (preset_name.empty() ? std::string("particle-lab") : preset_name) + "-" + stamp;
    fs::path file = dir / (stem + extension);
    for (int n = 2; fs::exists(file, ec); ++n) file = dir / (stem + "-" + std::to_string(n) + extension);
    return file;
}

}  // namespace pl::app
