#include "physics/stepping/thread_pool.hpp"

#include <algorithm>

namespace pl {

namespace {

// Spins briefly before sleeping: a simulation hands out a job every step (tens of
// microseconds apart for in-cache scenes), and a futex wake-up costs about as much.
constexpr int spin_iterations = 1 << 14;

void cpu_relax() {
#if defined(__x86_64__) || defined(__i386__)
    __builtin_ia32_pause();
#else
    std::this_thread::yield();
#endif
}

// Returns once `a` no longer holds `old`.
void wait_for_change(const std::atomic<std::uint64_t>& a, std::uint64_t old) {
    for (int i = 0; i < spin_iterations; ++i) {
        if (a.load(std::memory_order_acquire) != old) return;
        cpu_relax();
    }
    while (a.load(std::memory_order_acquire) == old) a.wait(old, std::memory_order_acquire);
}

}  // namespace

// Cached: hardware_concurrency() reads /sys on every call, far too slow for once per step.
int hardware_threads() {
    // Asked once: glibc answers hardware_concurrency() by reading sysfs, microseconds per call.
    static const int n = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    return n;
}

ThreadPool& ThreadPool::shared() {
    static ThreadPool pool;
    return pool;
}

ThreadPool::~ThreadPool() {
    const std::lock_guard lock(submit_);
    for (auto& slot : slots_) {
        slot->stop = true;
        slot->go.fetch_add(1, std::memory_order_release);
        slot->go.notify_one();
    }
    for (std::thread& t : workers_) t.join();
}

void ThreadPool::grow(std::size_t workers) {
    while (workers_.size() < workers) {
        slots_.push_back(std::make_unique<Slot>());
        Slot& slot = *slots_.back();
        const std::size_t participant = workers_.size() + 1;
        workers_.emplace_back([&slot, participant] { worker_loop(slot, participant); });
    }
}

void ThreadPool::work(Job& job, std::size_t participant) {
    for (std::size_t q = 0; q < job.participants; ++q) {
        Block& b = job.blocks[(participant + q) % job.participants];
        for (std::size_t k = b.next.fetch_add(1, std::memory_order_relaxed); k < b.end;
             k = b.next.fetch_add(1, std::memory_order_relaxed))
            job.fn(job.ctx, k);
    }
}

void ThreadPool::worker_loop(Slot& slot, std::size_t participant) {
    std::uint64_t seen = 0;
    for (;;) {
        wait_for_change(slot.go, seen);
        seen = slot.go.load(std::memory_order_acquire);
        if (slot.stop) return;
        std::uint64_t posted = Slot::tag(seen, Slot::posted);
        if (!slot.state.compare_exchange_strong(posted, Slot::tag(seen, Slot::claimed), std::memory_order_acq_rel))
            continue;  // withdrawn: the caller has done the work already
        work(*slot.job, participant);
        slot.done.store(seen, std::memory_order_release);
        slot.done.notify_one();
    }
}

void ThreadPool::run_erased(std::size_t tasks, std::size_t threads, TaskFn fn, void* ctx) {
    if (tasks == 0) return;
    const std::size_t helpers = std::min(tasks, threads) > 1 ? std::min(tasks, threads) - 1 : 0;
    std::unique_lock lock(submit_, std::defer_lock);
    if (helpers == 0 || !lock.try_lock()) {
        for (std::size_t k = 0; k < tasks; ++k) fn(ctx, k);
        return;
    }
    grow(helpers);
    const std::size_t participants = helpers + 1;
    if (block_capacity_ < participants) {
        blocks_ = std::make_unique<Block[]>(participants);
        block_capacity_ = participants;
    }
    for (std::size_t p = 0; p < participants; ++p) {
        blocks_[p].next.store(tasks * p / participants, std::memory_order_relaxed);
        blocks_[p].end = tasks * (p + 1) / participants;
    }
    Job job;
    job.fn = fn;
    job.ctx = ctx;
    job.blocks = blocks_.get();
    job.participants = participants;
    for (std::size_t w = 0; w < helpers; ++w) {
        Slot& slot = *slots_[w];
        const std::uint64_t handed = slot.go.load(std::memory_order_relaxed) + 1;
        slot.job = &job;
        slot.state.store(Slot::tag(handed, Slot::posted), std::memory_order_release);
        slot.go.store(handed, std::memory_order_release);
        slot.go.notify_one();
    }
    work(job, 0);
    for (std::size_t w = 0; w < helpers; ++w) {
        Slot& slot = *slots_[w];
        const std::uint64_t handed = slot.go.load(std::memory_order_relaxed);
        // A worker that has not woken up yet (the OS gave its core to someone else) is not
        // waited for: all tasks are done, so the job is withdrawn from it.
        std::uint64_t posted = Slot::tag(handed, Slot::posted);
        if (slot.state.compare_exchange_strong(posted, Slot::tag(handed, Slot::withdrawn), std::memory_order_acq_rel))
            continue;
        for (std::uint64_t d = slot.done.load(std::memory_order_acquire); d != handed;
             d = slot.done.load(std::memory_order_acquire))
            wait_for_change(slot.done, d);
    }
}

}  // namespace pl
