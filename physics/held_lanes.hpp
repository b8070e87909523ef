// Which particles of a chunk the flight phase must leave alone, as 64-bit vector lanes.
// Part of the fast stepping kernel (fast_kernel.hpp), included by fast_kernel.cpp alone, which
// is compiled with -fno-trapping-math (CMakeLists.txt) so that GCC if-converts these selects.
#pragma once

#include "fast_kernel.hpp"
#include "particle_state.hpp"

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>

namespace pl::fast {

// Lane masks of phase 1 are 64-bit: a byte-sized value in the vectorised loop would make GCC
// take 64 particles per iteration (one vector of bytes), spilling the 8-wide double vectors.
using LaneMask = std::int64_t;

// The particles of a chunk that phase 1 must leave alone (resting or frozen), as 64-bit lanes
// holding resting | frozen << 8 (zero for a free particle). They stay all zeros between chunks:
// only groups of 64 particles where a flag byte is set (found by ORing the bytes eight at a
// time, a reduction that vectorises) are widened, and cleared when the next chunk is marked.
// In flight most groups have none, and widening every byte cost more than the look.
class HeldLanes {
public:
    static constexpr std::size_t group = 64;

    const LaneMask* mark(const ParticleState& s, std::size_t begin, std::size_t end) {
        const std::uint8_t* const resting = s.resting.data() + begin;
        const std::uint8_t* const frozen = s.frozen.data() + begin;
        const std::size_t n = end - begin;
        clear();
        count_ = 0;
        for (std::size_t g = 0; g < n; g += group) {
            const std::size_t len = std::min(group, n - g);
            if (!any_set(resting + g, frozen + g, len)) continue;
            std::size_t held = 0;
            for (std::size_t j = g; j < g + len; ++j) {
                lanes_[j] = resting[j] | LaneMask{frozen[j]} << 8;
                held += lanes_[j] != 0;
            }
            count_ += held;
            widened_ |= std::uint32_t{1} << (g / group);
        }
        return lanes_;
    }

    // How many particles of the chunk last marked are held.
    std::size_t count() const { return count_; }

private:
    // Zeros the groups the last chunk widened.
    void clear() {
        for (; widened_ != 0; widened_ &= widened_ - 1)
            std::fill_n(lanes_ + std::countr_zero(widened_) * group, group, LaneMask{0});
    }

    static bool any_set(const std::uint8_t* a, const std::uint8_t* b, std::size_t n) {
        std::uint64_t any = 0;
        std::size_t i = 0;
        for (; i + 8 <= n; i += 8) {
            std::uint64_t wa, wb;
            std::memcpy(&wa, a + i, sizeof wa);
            std::memcpy(&wb, b + i, sizeof wb);
            any |= wa | wb;
        }
        for (; i < n; ++i) any |= static_cast<std::uint64_t>(a[i] | b[i]);
        return any != 0;
    }

    alignas(64) LaneMask lanes_[fast_chunk] = {};
    std::uint32_t widened_ = 0;  // groups holding a non-zero mask
    std::size_t count_ = 0;
};
static_assert(fast_chunk / HeldLanes::group <= 32);

}  // namespace pl::fast
