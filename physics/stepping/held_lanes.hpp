// Which particles of a chunk the flight phase must leave alone, as one bit per particle.
// Part of the fast stepping kernel (fast_kernel.hpp), included by fast_kernel.cpp alone, which
// is compiled with -fno-trapping-math (CMakeLists.txt) so that GCC if-converts these selects.
#pragma once

#include "physics/stepping/fast_kernel.hpp"
#include "physics/stepping/particle_state.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>

namespace pl::fast {

// Lane masks of the vector passes over held particles are 64-bit: a byte-sized value in a
// vectorised loop would make GCC take 64 particles per iteration (one vector of bytes),
// spilling the 8-wide double vectors.
using LaneMask = std::int64_t;

// One bit per particle of a group of 64 (bit j: particle g + j): what phase 1 is told to leave
// alone and what it leaves for phase 2. A word per group, instead of a 64-bit lane per particle,
// so that finding the few set ones is a look at a few words.
using LaneBits = std::uint64_t;
constexpr std::size_t lane_group = 64;
constexpr std::size_t chunk_groups = (fast_chunk + lane_group - 1) / lane_group;

// bit_of[j] = bit j: how a vector loop reads the bit of particle j of a group in 8-particle
// vectors (a variable shift, with its 32-bit count, makes GCC take 16 per iteration).
alignas(64) inline constexpr auto bit_of = [] {
    std::array<LaneBits, lane_group> bits{};
    for (std::size_t j = 0; j < lane_group; ++j) bits[j] = LaneBits{1} << j;
    return bits;
}();

// bit_of[j] where `set`, else 0, as a mask (a conditional here is left as a branch, which stops
// the vectoriser).
inline LaneBits bit_if(bool set, std::size_t j) { return bit_of[j] & (LaneBits{0} - LaneBits{set}); }

// The particles of a chunk that phase 1 must leave alone (resting or frozen). bits() has one
// bit per particle; lanes() widens them, for the passes over a chunk with many held particles,
// to 64-bit lanes holding resting | frozen << 8 (zero for a free particle). In flight most
// groups of 64 have none, found by ORing their bytes eight at a time (a reduction that vectorises).
class HeldLanes {
public:
    void mark(const ParticleState& s, std::size_t begin, std::size_t end) {
        resting_ = s.resting.data() + begin;
        frozen_ = s.frozen.data() + begin;
        n_ = end - begin;
        count_ = 0;
        lanes_ready_ = false;
        for (std::size_t g = 0; g < n_; g += lane_group) {
            const std::size_t len = std::min(lane_group, n_ - g);
            const LaneBits held =
                any_set(resting_ + g, frozen_ + g, len) ? nonzero_bits(resting_ + g, frozen_ + g, len) : 0;
            bits_[g / lane_group] = held;
            count_ += static_cast<std::size_t>(std::popcount(held));
        }
    }

    const LaneBits* bits() const { return bits_; }

    // How many particles of the chunk last marked are held.
    std::size_t count() const { return count_; }

    // The chunk's held particles as lanes (see above); the groups of the chunk widened before
    // are zeroed first.
    const LaneMask* lanes() {
        if (lanes_ready_) return lanes_;
        lanes_ready_ = true;
        for (; widened_ != 0; widened_ &= widened_ - 1)
            std::fill_n(lanes_ + std::countr_zero(widened_) * lane_group, lane_group, LaneMask{0});
        for (std::size_t g = 0; g < n_; g += lane_group) {
            if (bits_[g / lane_group] == 0) continue;
            for (std::size_t j = g; j < std::min(n_, g + lane_group); ++j)
                lanes_[j] = resting_[j] | LaneMask{frozen_[j]} << 8;
            widened_ |= std::uint32_t{1} << (g / lane_group);
        }
        return lanes_;
    }

private:
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

    // Bit j set where a[j] | b[j] is non-zero, eight bytes at a time: the top bit of each
    // non-zero byte, then the eight top bits gathered by one multiply (bit 8k goes to 56 + k).
    static LaneBits nonzero_bits(const std::uint8_t* a, const std::uint8_t* b, std::size_t n) {
        constexpr std::uint64_t low7 = 0x7f7f7f7f7f7f7f7f;
        LaneBits bits = 0;
        std::size_t i = 0;
        for (; i + 8 <= n; i += 8) {
            std::uint64_t wa, wb;
            std::memcpy(&wa, a + i, sizeof wa);
            std::memcpy(&wb, b + i, sizeof wb);
            const std::uint64_t w = wa | wb;
            const std::uint64_t top = (((w & low7) + low7) | w) & ~low7;
            bits |= (((top >> 7) * 0x0102040810204080) >> 56) << i;
        }
        for (; i < n; ++i) bits |= LaneBits{(a[i] | b[i]) != 0} << i;
        return bits;
    }

    const std::uint8_t* resting_ = nullptr;
    const std::uint8_t* frozen_ = nullptr;
    std::size_t n_ = 0;
    LaneBits bits_[chunk_groups] = {};
    std::size_t count_ = 0;
    alignas(64) LaneMask lanes_[fast_chunk] = {};
    std::uint32_t widened_ = 0;  // groups of lanes_ holding a non-zero mask
    bool lanes_ready_ = false;   // lanes_ is the chunk last marked
};
static_assert(chunk_groups <= 32);

}  // namespace pl::fast
