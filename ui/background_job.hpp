// A study running on its own thread so the ui stays responsive: progress, cancel, result.
// The work gets copies of everything it reads (never the live session).
#pragma once

#include <atomic>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

namespace pl::ui {

template <class Result>
class BackgroundJob {
public:
    // `work(progress, cancel)` runs on the job's thread; progress takes a fraction in [0, 1].
    using Work = std::function<Result(const std::function<void(double)>& progress, const std::atomic<bool>& cancel)>;

    BackgroundJob() = default;
    BackgroundJob(const BackgroundJob&) = delete;
    BackgroundJob& operator=(const BackgroundJob&) = delete;
    ~BackgroundJob() { stop(); }

    // Starts `work`, first stopping (cancel and wait for) a run still going.
    void start(Work work) {
        stop();
        shared_ = std::make_shared<Shared>();
        result_.reset();
        error_.clear();
        std::shared_ptr<Shared> shared = shared_;
        thread_ = std::thread([shared, work = std::move(work)] {
            auto progress = [shared](double f) { shared->progress.store(f, std::memory_order_relaxed); };
            try {
                Result r = work(progress, shared->cancel);
                std::lock_guard<std::mutex> lock(shared->mutex);
                shared->result = std::move(r);
            } catch (const std::exception& e) {
                std::lock_guard<std::mutex> lock(shared->mutex);
                shared->error = e.what();
            }
            shared->done.store(true, std::memory_order_release);
        });
    }

    void cancel() {
        if (shared_) shared_->cancel.store(true);
    }

    // Call once a frame: collects a finished run's result.
    void poll() {
        if (!shared_ || !shared_->done.load(std::memory_order_acquire)) return;
        if (thread_.joinable()) thread_.join();
        std::lock_guard<std::mutex> lock(shared_->mutex);
        result_ = std::move(shared_->result);
        error_ = shared_->error;
        shared_.reset();
    }

    bool running() const { return shared_ != nullptr; }
    bool cancelling() const { return shared_ && shared_->cancel.load(); }
    double progress() const { return shared_ ? shared_->progress.load(std::memory_order_relaxed) : 0.0; }
    const std::optional<Result>& result() const { return result_; }
    const std::string& error() const { return error_; }  // what the work threw, if it threw
    void clear() {
        result_.reset();
        error_.clear();
    }

private:
    struct Shared {
        std::atomic<bool> cancel{false};
        std::atomic<bool> done{false};
        std::atomic<double> progress{0.0};
        std::mutex mutex;
        std::optional<Result> result;
        std::string error;
    };

    void stop() {
        if (!shared_) return;
        shared_->cancel.store(true);
        if (thread_.joinable()) thread_.join();
        shared_.reset();
    }

    std::shared_ptr<Shared> shared_;
    std::thread thread_;
    std::optional<Result> result_;
    std::string error_;
};

}  // namespace pl::ui
