// Threaded loops of the collision pass whose results do not depend on the threads: each slice of
// the work writes only its own output, and the outputs are joined in slice order.
#pragma once

#include "physics/stepping/thread_pool.hpp"

#include <cstddef>
#include <vector>

namespace pl::collide {

// The tasks for_ranges splits n items into: one below 8192 items or on one thread.
inline std::size_t range_tasks(std::size_t n, std::size_t threads) { return threads > 1 && n >= 8192 ? threads : 1; }

// Runs body(begin, end, task) over [0, n) in range_tasks(n, threads) contiguous ranges (each
// range writes only its own items, or its task's slot, so the result does not depend on the
// threads).
template <class Body>
void for_ranges(std::size_t n, std::size_t threads, Body&& body) {
    const std::size_t tasks = range_tasks(n, threads);
    if (tasks == 1) return body(std::size_t{0}, n, std::size_t{0});
    auto task = [&](std::size_t k) { body(n * k / tasks, n * (k + 1) / tasks, k); };
    ThreadPool::shared().run(tasks, threads, task);
}

// Returns fill(own), where `own` is an empty vector holding `buffer`'s storage (swapped in, and
// back into `buffer` after): a task that fills one of several buffers whose headers lie side by
// side in memory pushes into a header of its own, where pushes into neighbouring headers moved
// their shared cache line between the cores at every push.
template <class T, class Fill>
decltype(auto) fill_privately(std::vector<T>& buffer, Fill&& fill) {
    std::vector<T> own;
    own.swap(buffer);
    own.clear();
    struct SwapBack {
        std::vector<T>& own;
        std::vector<T>& buffer;
        ~SwapBack() { own.swap(buffer); }
    } back{own, buffer};
    return fill(own);
}

// Appends to `out` what scan(begin, end, buffer) appends over [0, count): in one go on one
// thread or below `grain` items, else in 4 slices per thread, each into its own buffer of
// `buffers`, joined in order (the same items in the same order on any number of threads).
template <class T, class Scan>
void append_in_slices(std::size_t count, std::size_t threads, std::size_t grain, std::vector<std::vector<T>>& buffers,
                      std::vector<T>& out, Scan&& scan) {
    const std::size_t slices = threads > 1 && count >= grain ? 4 * threads : 1;
    if (slices == 1) return scan(std::size_t{0}, count, out);
    buffers.resize(slices);
    auto task = [&](std::size_t k) {
        fill_privately(buffers[k], [&](std::vector<T>& own) { scan(count * k / slices, count * (k + 1) / slices, own); });
    };
    ThreadPool::shared().run(slices, threads, task);
    for (const std::vector<T>& buffer : buffers) out.insert(out.end(), buffer.begin(), buffer.end());
}

}  // namespace pl::collide
