// Threaded loops of the collision pass whose results do not depend on the threads: each slice of
// the work writes only its own output, and the outputs are joined in slice order.
#pragma once

#include "physics/stepping/thread_pool.hpp"

#include <cstddef>
#include <vector>

namespace pl::collide {

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
        buffers[k].clear();
        scan(count * k / slices, count * (k + 1) / slices, buffers[k]);
    };
    ThreadPool::shared().run(slices, threads, task);
    for (const std::vector<T>& buffer : buffers) out.insert(out.end(), buffer.begin(), buffer.end());
}

}  // namespace pl::collide
