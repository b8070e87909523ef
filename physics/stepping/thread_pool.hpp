// A small persistent pool of worker threads for data-parallel loops over particles.
// The calling thread takes part in the work, so a job of one task never touches another thread.
// Which thread runs which task is not fixed; callers make results independent of it by giving
// every task its own output (the kernels split particles into contiguous ranges).
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

namespace pl {

class ThreadPool {
public:
    ThreadPool() = default;
    ~ThreadPool();
    ThreadPool(const ThreadPool&) = delete;
    ThreadPool& operator=(const ThreadPool&) = delete;

    // The process-wide pool the simulation kernels share (workers are created on first use).
    static ThreadPool& shared();

    // Runs task(k) once for every k in [0, tasks), spread over the calling thread and up to
    // `threads - 1` workers; returns when every task has finished. Tasks must not throw.
    // Each thread first runs its own contiguous block of tasks (the same block job after job,
    // so the data of a simulation's particle ranges stays in that core's cache), then takes
    // over tasks of threads that are slower or were not scheduled.
    // When another caller is using the pool (e.g. a background study), the tasks run on the
    // calling thread instead: slower, never a deadlock, and the same results.
    template <class Task>
    void run(std::size_t tasks, std::size_t threads, Task& task) {
        run_erased(tasks, threads, [](void* t, std::size_t k) { (*static_cast<Task*>(t))(k); }, &task);
    }

    std::size_t worker_count() const { return workers_.size(); }

private:
    using TaskFn = void (*)(void*, std::size_t);
    // Next task of one participant's block [next, end); on its own cache line.
    struct alignas(64) Block {
        std::atomic<std::size_t> next{0};
        std::size_t end = 0;
    };
    struct Job {
        TaskFn fn = nullptr;
        void* ctx = nullptr;
        Block* blocks = nullptr;
        std::size_t participants = 0;  // the caller is 0, worker w is w + 1
    };
    // One per worker: the caller hands job number g over by posting it in `state` and setting
    // `go` to g; the worker claims it in `state`, runs tasks and sets `done` to g. After its own
    // tasks the caller withdraws a job nobody claimed, and waits only for claimed ones. A worker
    // only looks at its own slot, and claim and withdrawal are one compare-and-swap each on a
    // value that carries g, so no job is run late, twice, or after the caller has returned.
    struct Slot {
        enum Phase : std::uint64_t { posted = 1, claimed = 2, withdrawn = 3 };
        static std::uint64_t tag(std::uint64_t job, Phase phase) { return job << 2 | phase; }
        std::atomic<std::uint64_t> go{0}, done{0}, state{0};
        Job* job = nullptr;
        std::atomic<bool> stop{false};
    };

    void run_erased(std::size_t tasks, std::size_t threads, TaskFn fn, void* ctx);
    void grow(std::size_t workers);
    static void work(Job& job, std::size_t participant);
    static void worker_loop(Slot& slot, std::size_t participant);

    std::mutex submit_;  // one job at a time
    std::vector<std::unique_ptr<Slot>> slots_;
    std::unique_ptr<Block[]> blocks_;
    std::size_t block_capacity_ = 0;
    std::vector<std::thread> workers_;
};

// Threads a simulation uses when its setting is 0: all hardware threads (at least 1).
int hardware_threads();

}  // namespace pl
