// A tiny, portable, seeded generator: the same seed gives the same numbers on every platform
// (std::uniform_real_distribution is implementation-defined, so it is not used).
#pragma once

#include <cstdint>

namespace pl {

// SplitMix64 (Steele, Lea, Flood 2014).
struct SplitMix64 {
    std::uint64_t state;
    explicit SplitMix64(std::uint64_t seed) : state(seed) {}
    std::uint64_t next() {
        std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    double uniform01() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
    double uniform(double lo, double hi) { return lo + (hi - lo) * uniform01(); }
};

}  // namespace pl
