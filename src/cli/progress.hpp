// Progress of long work on stderr, only when stderr is a terminal and the work has run for
// progress_delay_s (short commands and pipes stay silent), never under --quiet. The line shows
// the percentage done (and steps done of the total with their rate) and the time left, redrawn
// at most every 0.2 s.
#pragma once

#include <chrono>
#include <cstdint>
#include <mutex>
#include <string>

namespace pl::cli {

// --quiet: no progress and no warnings on stderr (errors are still printed).
void set_quiet(bool quiet);
bool quiet();

// Seconds of work before the first progress line: 2, or PARTICLE_LAB_PROGRESS_DELAY_S when set
// (the tests set 0 so that a short run shows its progress).
double progress_delay_s();

class Progress {
public:
    // `total` > 0: update_count() reports `unit`s done of `total`; otherwise update() fractions.
    explicit Progress(std::string what, std::uint64_t total = 0, std::string unit = "");
    ~Progress();
    void update(double fraction);     // thread-safe: studies report from worker threads
    void update_count(std::uint64_t done);
    void done();

private:
    void draw(double fraction, std::uint64_t count);
    std::mutex mutex_;
    std::string what_, unit_;
    std::uint64_t total_ = 0;
    bool enabled_ = false;
    std::size_t drawn_width_ = 0;
    std::chrono::steady_clock::time_point start_, last_draw_;
};

}  // namespace pl::cli
