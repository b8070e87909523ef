#include "cli/progress.hpp"

#include <fmt/format.h>

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>

namespace pl::cli {

namespace {
bool quiet_flag = false;

std::string duration_text(double seconds) {
    if (seconds < 90) return fmt::format("{:.0f} s", seconds);
    if (seconds < 5400) return fmt::format("{:.0f} min", seconds / 60);
    return fmt::format("{:.1f} h", seconds / 3600);
}
}  // namespace

void set_quiet(bool quiet) { quiet_flag = quiet; }
bool quiet() { return quiet_flag; }

double progress_delay_s() {
    const char* text = std::getenv("PARTICLE_LAB_PROGRESS_DELAY_S");
    char* end = nullptr;
    const double value = text ? std::strtod(text, &end) : 0.0;
    return text && end != text && value >= 0.0 ? value : 2.0;
}

Progress::Progress(std::string what, std::uint64_t total, std::string unit)
    : what_(std::move(what)), unit_(std::move(unit)), total_(total),
      enabled_(!quiet_flag && isatty(STDERR_FILENO) == 1), start_(std::chrono::steady_clock::now()) {}

Progress::~Progress() { done(); }

void Progress::update(double fraction) { draw(std::clamp(fraction, 0.0, 1.0), 0); }

void Progress::update_count(std::uint64_t done) {
    draw(total_ ? std::min(1.0, static_cast<double>(done) / static_cast<double>(total_)) : 0.0, done);
}

void Progress::draw(double fraction, std::uint64_t count) {
    if (!enabled_) return;
    const std::lock_guard lock(mutex_);
    const auto now = std::chrono::steady_clock::now();
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    if (elapsed < progress_delay_s() || (drawn_width_ > 0 && now - last_draw_ < std::chrono::milliseconds(200))) return;
    last_draw_ = now;
    std::string line = fmt::format("{}: {:3d}%", what_, static_cast<int>(fraction * 100.0));
    if (total_) line += fmt::format(", {}/{} {}, {:.3g} {}/s", count, total_, unit_, static_cast<double>(count) / elapsed, unit_);
    if (fraction > 0) line += ", " + duration_text(elapsed * (1.0 - fraction) / fraction) + " left";
    const std::size_t width = line.size();
    line.append(drawn_width_ > width ? drawn_width_ - width : 0, ' ');  // wipe the longer line before
    drawn_width_ = width;
    std::fprintf(stderr, "\r%s", line.c_str());
    std::fflush(stderr);
}

void Progress::done() {
    const std::lock_guard lock(mutex_);
    if (!enabled_ || drawn_width_ == 0) return;
    std::fprintf(stderr, "\r%*s\r", static_cast<int>(drawn_width_), "");
    std::fflush(stderr);
    drawn_width_ = 0;
}

}  // namespace pl::cli
